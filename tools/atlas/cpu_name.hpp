// The CPU named on every chart of the atlas: its model name with, on x86, its family and model
// numbers ("AMD EPYC (family 25 model 17)"), which tell the generations of one brand name apart.
#pragma once

#include <string>

namespace edgewise::atlas {

// From /proc/cpuinfo; "unknown CPU" where it says nothing usable.
std::string cpu_name();

}  // namespace edgewise::atlas
