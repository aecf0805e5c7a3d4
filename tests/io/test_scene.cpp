// The scene in the world: the flow direction (solved in the wind frame, reported turned), a rotor sail's
// course (thrust and side force), the span's totals, rpm; their keys, round-trips and errors.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

#include "io/case_file.hpp"
#include "io/hdf5_io.hpp"
#include "io/case_parse.hpp"
#include "support.hpp"

using namespace magnus;
using test::error_of;
using test::parse;

namespace {

/// A scene with extra [cylinder] and [flow] lines, on a small grid.
std::string scene(const std::string& cylinder = "", const std::string& flow = "", const std::string& more = "") {
  return "[cylinder]\nradius = 0.1\nspin = 100.0\n" + cylinder + "[flow]\nspeed = 10.0\n" + flow +
         "[grid]\nn_theta = 32\n" + more;
}

}  // namespace

TEST_CASE("course_force: thrust and side force from a known lift, drag and angles", "[physics][scene]") {
  // Wind on the starboard beam (towards +y), ship along +x: the lift L (CCW of the wind, here −100 N/m, i.e.
  // towards +x) is all thrust, the drag D = 10 N/m all side force to port (+y).
  const CourseForce beam = course_force(10.0, -100.0, 90.0, 0.0);
  CHECK(beam.thrust == 100.0);
  CHECK(beam.side == 10.0);
  // The same relative angle anywhere in the world gives the same forces.
  const CourseForce turned = course_force(10.0, -100.0, 30.0, -60.0);
  CHECK(turned.thrust == Approx(100.0).epsilon(1e-14));
  CHECK(turned.side == Approx(10.0).epsilon(1e-14));
  // Wind from dead astern (towards the course): the drag pushes ahead, the lift is across.
  const CourseForce astern = course_force(10.0, -100.0, 45.0, 45.0);
  CHECK(astern.thrust == 10.0);
  CHECK(astern.side == -100.0);
  // Apparent wind 30° off the bow on the port side (flowing towards 180° + 30° from a course of 0°):
  // φ = 210°: T = D cos φ − L sin φ, S = D sin φ + L cos φ.
  const double phi = 210.0 * M_PI / 180.0;
  const CourseForce bow = course_force(10.0, 100.0, 210.0, 0.0);
  CHECK(bow.thrust == Approx(10.0 * std::cos(phi) - 100.0 * std::sin(phi)).epsilon(1e-14));
  CHECK(bow.side == Approx(10.0 * std::sin(phi) + 100.0 * std::cos(phi)).epsilon(1e-14));
  // Turning by multiples of 90° is exact (no 6e-17 from cos 90°).
  const WorldForce q = world_force(0.0, 5.0, -270.0);
  CHECK(q.x == -5.0);
  CHECK(q.y == 0.0);
}

TEST_CASE("flow.direction, flow.course, cylinder.span: read, echoed, round-trip", "[io][case][scene]") {
  const Case d = parse(scene());
  CHECK(d.scene.direction_deg == 0.0);
  CHECK_FALSE(d.scene.course_deg);
  CHECK(d.scene.span == 0.0);
  const Case c = parse(scene("span = 30.0\n", "direction = -135.5\ncourse = 270\n"));
  CHECK(c.scene.direction_deg == -135.5);
  REQUIRE(c.scene.course_deg);
  CHECK(*c.scene.course_deg == 270.0);
  CHECK(c.scene.span == 30.0);
  // The resolved case holds them, and reads back to the same case.
  CHECK(c.source_text.find("direction = -135.5\n") != std::string::npos);
  CHECK(c.source_text.find("course = 270.0\n") != std::string::npos);
  CHECK(c.source_text.find("span = 30.0\n") != std::string::npos);
  const Case back = parse(c.source_text);
  CHECK(back.scene.direction_deg == c.scene.direction_deg);
  CHECK(*back.scene.course_deg == *c.scene.course_deg);
  CHECK(back.scene.span == c.scene.span);
  CHECK(back.source_text == c.source_text);
  // --set overrides them like any key.
  const Case o = parse(scene(), {"flow.direction=90", "cylinder.span=2.5", "flow.course=-10"});
  CHECK(o.scene.direction_deg == 90.0);
  CHECK(o.scene.span == 2.5);
  CHECK(*o.scene.course_deg == -10.0);
}

TEST_CASE("cylinder.rpm: ω = rpm·2π/60, echoed as rpm, round-trips to the same ω", "[io][case][scene]") {
  const std::string text = "[cylinder]\nradius = 2.5\nrpm = 150\n[flow]\nspeed = 12.0\n";
  const Case c = parse(text);
  CHECK(c.scene.spin == Approx(150.0 * 2.0 * M_PI / 60.0).epsilon(1e-15));
  CHECK(c.scene.rpm() == Approx(150.0).epsilon(1e-15));
  CHECK(c.source_text.find("rpm = 150.0\n") != std::string::npos);
  CHECK(c.source_text.find("spin =") == std::string::npos);
  const Case back = parse(c.source_text);
  CHECK(back.scene.spin == c.scene.spin);  // the same double: the same conversion of the same input
  CHECK(back.source_text == c.source_text);
  // An override of the spin replaces the rpm, and the echo follows.
  const Case s = parse(text, {"cylinder.spin=10"});
  CHECK(s.source_text.find("spin = 10.0\n") != std::string::npos);
  CHECK(s.source_text.find("rpm") == std::string::npos);
}

TEST_CASE("direction, course, span: one-line range and type errors naming the key", "[io][case][scene]") {
  CHECK(error_of(scene("", "direction = 400.0\n")) ==
        "test.toml: flow.direction: 400 is out of range: must be in [-360, 360] (deg, CCW from +x)");
  CHECK(error_of(scene("", "course = -360.5\n")) ==
        "test.toml: flow.course: -360.5 is out of range: must be in [-360, 360] (deg, CCW from +x)");
  CHECK(error_of(scene("", "course = \"north\"\n")) == "test.toml: flow.course: expected a number, got a string");
  CHECK(error_of(scene("", "direction = nan\n")) == "test.toml: flow.direction: must be finite, got nan");
  CHECK(error_of(scene("span = 0.0\n")) == "test.toml: cylinder.span: 0 is out of range: must be > 0 and <= 1e6 (m)");
  CHECK(error_of(scene("span = -3\n")) ==
        "test.toml: cylinder.span: -3 is out of range: must be > 0 and <= 1e6 (m)");
  CHECK(error_of(scene("", "direction = 360\n")) == "");
  // A total that overflows is refused at the input to blame.
  // (ρUΓ = 2.5e302 N/m is finite, and so is every other figure of the scene; over 1e6 m it is not.)
  const std::string big = "[cylinder]\nradius = 1.0\nspin = 8e101\n[flow]\nspeed = 5e99\ndensity = 1e100\n";
  CHECK(error_of(big) == "");
  CHECK(error_of(big, {"cylinder.span=1e6"}) ==
        "test.toml: cylinder.spin: 8e+101 is too large: the total lift ρUΓ·b is not finite");
  // In a turned world u_x and u_y are stored together.
  CHECK(error_of(scene("", "direction = 90\n", "[output]\nfields = [\"u_x\", \"pressure\"]\n")) ==
        "test.toml: output.fields: \"u_x\" needs \"u_y\" too when flow.direction is not 0 (each mixes both "
        "components of the wind frame)");
  CHECK(error_of(scene("", "", "[output]\nfields = [\"u_x\"]\n")) == "");
}

TEST_CASE("key hints: span, direction and course are keys, and spin and span are never mistaken", "[io][case][scene]") {
  const auto& keys = case_keys();
  for (const char* k : {"cylinder.span", "flow.direction", "flow.course"})
    CHECK(std::find(keys.begin(), keys.end(), k) != keys.end());
  CHECK(nearest_key("cylinder.spen") == "");  // as near spin as span: no guess
  CHECK(nearest_key("cylinder.spinn") == "cylinder.spin");
  CHECK(nearest_key("cylinder.spans") == "cylinder.span");
  CHECK(nearest_key("flow.directon") == "flow.direction");
  CHECK(nearest_key("flow.coarse") == "flow.course");
  CHECK(nearest_key("flow.heading") == "flow.course");
  CHECK(nearest_key("cylinder.length") == "cylinder.span");
  CHECK(error_of(scene("spen = 3\n")) ==
        "test.toml: unknown key cylinder.spen (keys of [cylinder]: radius, spin, spin_ratio, rpm, span)");
}
