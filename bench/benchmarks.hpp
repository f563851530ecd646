// Benchmarks that depend on the CPU (one per supported ISA) are registered at run time.
#pragma once

namespace edgewise::bench {

// Coverage/<isa>/area:<px> for every supported ISA, the reference included.
void register_coverage_benchmarks();

}  // namespace edgewise::bench
