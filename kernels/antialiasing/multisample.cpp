#include "edgewise/multisample.hpp"

#include <stdexcept>
#include <string>

namespace edgewise {
namespace {

// Direct3D 11's standard patterns (the same as Vulkan's standard sample locations).
constexpr SampleOffset kOne[] = {{0, 0}};
constexpr SampleOffset kTwo[] = {{4, 4}, {-4, -4}};
constexpr SampleOffset kFour[] = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
constexpr SampleOffset kEight[] = {{1, -3}, {-1, 3},  {5, 1}, {-3, -5},
                                   {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
constexpr SampleOffset kSixteen[] = {{1, 1},  {-1, -3}, {-3, 2}, {4, -1}, {-5, -2}, {2, 5},
                                     {5, 3},  {3, -5},  {-2, 6}, {0, -7}, {-4, -6}, {-6, 4},
                                     {-8, 0}, {7, -4},  {6, 7},  {-7, -8}};

}  // namespace

bool is_standard_sample_count(int samples) {
  return samples == 1 || samples == 2 || samples == 4 || samples == 8 || samples == 16;
}

std::span<const SampleOffset> standard_sample_pattern(int samples) {
  switch (samples) {
    case 1:
      return kOne;
    case 2:
      return kTwo;
    case 4:
      return kFour;
    case 8:
      return kEight;
    case 16:
      return kSixteen;
    default:
      throw std::invalid_argument("standard_sample_pattern: " + std::to_string(samples) +
                                  " samples per pixel has no standard pattern (1, 2, 4, 8 or 16)");
  }
}

}  // namespace edgewise
