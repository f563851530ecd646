// The sampling kernels (sample.hpp's sample(), and the texture lookups of draw()), compiled
// once per ISA.
#include "../src/isa_build.hpp"

#include "../generic/sample_batch-inl.hpp"
