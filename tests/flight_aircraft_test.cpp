// The procedural aircraft: every preset is a closed mesh of the stated size, and the
// shipped sets are found by name and hold what the catalog promises.
#include "flight/aircraft_catalog.h"
#include "flight/aircraft_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace skylit::flight {
namespace {

TEST(AircraftMesh, PresetsAreClosedAndAsLargeAsTheirModels) {
  // Overall span (y) and length (x) from the public figures quoted in aircraft_mesh.cpp.
  struct Size {
    const char* name;
    double span, length;
  };
  for (const Size& s : {Size{"glider", 15.0, 6.59}, Size{"light-single", 11.0, 8.28}, Size{"airliner", 34.1, 37.57},
                        Size{"helicopter", 10.69, 10.93}, Size{"balloon", 18.8, 18.8}}) {
    const Mesh m = make_aircraft_mesh(s.name);
    EXPECT_TRUE(is_closed(m)) << s.name;
    const Bounds b = bounds(m);
    EXPECT_NEAR(b.size().y, s.span, 0.02 * s.span) << s.name;
    if (std::string(s.name) != "helicopter") {  // the rotor disc overhangs the 10.93 m fuselage
      EXPECT_NEAR(b.size().x, s.length, 0.02 * s.length) << s.name;
    }
  }
  EXPECT_THROW(make_aircraft_mesh("zeppelin"), std::invalid_argument);
}

TEST(AircraftCatalog, FindsTheShippedSetsByName) {
  const auto names = shipped_aircraft();
  for (const auto& p : aircraft_presets()) {
    ASSERT_NE(std::find(names.begin(), names.end(), p.name), names.end()) << p.name;
    const SphereSet s = load_aircraft(p.name);
    EXPECT_EQ(s.name, p.name);
    EXPECT_EQ(static_cast<int>(s.spheres.size()), p.suggested_k);
    EXPECT_TRUE(s.has_fit_error);
    EXPECT_GT(s.fit_error.volume_error, 0.0);
  }
  EXPECT_EQ(load_aircraft(aircraft_data_dir() + "/glider.json").name, "glider");
  EXPECT_THROW(load_aircraft("zeppelin"), SphereSetError);
}

}  // namespace
}  // namespace skylit::flight
