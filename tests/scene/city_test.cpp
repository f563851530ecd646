// The city of testing/scene/city.hpp: culled frames give the whole frames' images, bit for bit,
// on every ISA and from several views, while culling most of the props from the street.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "edgewise/edgewise.hpp"
#include "isa_params.hpp"
#include "scene/city.hpp"
#include "scene/city_frame.hpp"

namespace edgewise::test {
namespace {

constexpr std::int32_t kCityTestWidth = 320, kCityTestHeight = 180;

scene::City small_city() {
  scene::CityOptions options;
  options.blocks_per_side = 6;
  options.props_per_block = 10;
  options.prop_rings = 6;
  options.prop_segments = 8;
  return scene::make_city(options);
}

std::vector<std::uint8_t> pixels_of(const Framebuffer& target) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(target.width()) * target.height() * 4);
  target.read_rgba8(rgba);
  return rgba;
}

class CityCulling : public IsaTest {};

TEST_P(CityCulling, CulledFramesEqualWholeFrames) {
  scene::City city = small_city();
  ASSERT_EQ(city.objects.size(), 6u * 6u * 4u + 1u + 6u * 6u * 10u);
  const float aspect = static_cast<float>(kCityTestWidth) / kCityTestHeight;
  // The street view, one from above the roofs and one across the city from its edge.
  const scene::SceneCamera street = city.camera;
  scene::SceneCamera above = street;
  above.eye = {street.eye.x + 30.0f, 90.0f, street.eye.z - 40.0f};
  above.target = {0.0f, 0.0f, 0.0f};
  scene::SceneCamera across = street;
  across.eye = {-200.0f, 5.0f, 3.0f};
  across.target = {0.0f, 10.0f, 0.0f};
  Framebuffer whole(kCityTestWidth, kCityTestHeight), culled(kCityTestWidth, kCityTestHeight);
  OcclusionBuffer occlusion(kCityTestWidth, kCityTestHeight);
  scene::Mesh visible;
  scene::CityFrameOptions options;
  options.isa = isa();
  int view_index = 0;
  for (const scene::SceneCamera& camera : {street, above, across}) {
    city.camera = camera;
    const Mat4 view = scene::city_view(city, aspect);
    scene::draw_city(whole, city, view, options);
    const scene::CityFrame frame =
        scene::draw_city_culled(culled, occlusion, city, view, options, visible);
    EXPECT_EQ(pixels_of(whole), pixels_of(culled)) << "view " << view_index;
    if (view_index == 0) {
      // From the street, the buildings hide most of the trees.
      const std::size_t props = city.objects.size() - city.first_prop();
      EXPECT_LT(frame.objects_drawn - city.first_prop(), props / 4) << "too few props culled";
    }
    ++view_index;
  }
}

INSTANTIATE_TEST_SUITE_P(Isas, CityCulling, ::testing::ValuesIn(every_isa()), isa_test_name);

}  // namespace
}  // namespace edgewise::test
