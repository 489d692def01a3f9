// configs/ode.yaml end to end: the ODE physics plugin is listed with its parameters, the scenario
// runs, reruns give identical bytes and every transport gives the same bytes.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "command_runner.hpp"

namespace swarmnet::testing {
namespace {

const std::string kOdeScenario = std::string(SWARMNET_SOURCE_DIR) + "/configs/ode.yaml";

void run_ode(const std::filesystem::path& dir, const std::string& extra = "") {
  const auto result = run_swarmnet("run " + kOdeScenario + " --set duration_s=5 --quiet --out " +
                                   dir.string() + extra);
  ASSERT_EQ(result.exit_code, 0) << result.output;
}

TEST(OdeRun, PluginIsListedWithEveryParameter) {
  const auto result = run_swarmnet("plugins ode");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* parameter :
       {"robot_mass_kg", "wheel_friction", "contact_friction", "object_floor_friction",
        "gravity_mps2", "contact_erp", "contact_cfm_m_per_n", "contact_surface_layer_m",
        "max_substep_s", "max_travel_fraction", "solver_iterations", "drive"}) {
    EXPECT_NE(result.output.find(parameter), std::string::npos) << parameter;
  }
}

TEST(OdeRun, RerunsAndTransportsGiveIdenticalBytes) {
  TempDir dir;
  run_ode(dir.path() / "first");
  const std::string positions = read_file(dir.path() / "first" / "positions.bin");
  const std::string packets = read_file(dir.path() / "first" / "packets.csv");
  ASSERT_FALSE(positions.empty());
  ASSERT_FALSE(packets.empty());
  for (const char* transport : {"shm", "inproc", "uds", "tcp"}) {
    const auto out = dir.path() / transport;
    run_ode(out, std::string(" --transport ") + transport);
    EXPECT_TRUE(read_file(out / "positions.bin") == positions) << transport;
    EXPECT_TRUE(read_file(out / "packets.csv") == packets) << transport;
    EXPECT_TRUE(read_file(out / "mobility.ns2") == read_file(dir.path() / "first" / "mobility.ns2"))
        << transport;
  }
}

// The robots really move under ODE, and not as under kinematic2d: the drive accelerates from
// rest, so the first steps' positions differ.
TEST(OdeRun, MotionDiffersFromKinematic2d) {
  TempDir dir;
  run_ode(dir.path() / "ode");
  run_ode(dir.path() / "kinematic", " --set physics.plugin=kinematic2d --set physics.params={}");
  EXPECT_FALSE(read_file(dir.path() / "ode" / "positions.bin") ==
               read_file(dir.path() / "kinematic" / "positions.bin"));
}

// Movable objects: their poses go to objects.csv, one row per object and step, identical on a
// rerun; kinematic2d refuses them with a message that says what to do.
const std::string kObjects =
    " --set 'arena.objects=[{shape: box, x_m: 100, y_m: 100, size_x_m: 0.3, size_y_m: 0.3},"
    "{shape: cylinder, x_m: 120, y_m: 100, radius_m: 0.1, mass_kg: 0.2}]'";

TEST(OdeRun, WritesObjectPosesBesideThePositions) {
  TempDir dir;
  run_ode(dir.path() / "first", kObjects);
  run_ode(dir.path() / "second", kObjects);
  const std::string objects = read_file(dir.path() / "first" / "objects.csv");
  EXPECT_TRUE(objects == read_file(dir.path() / "second" / "objects.csv"));
  std::istringstream lines(objects);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "step,time_ns,object,x_m,y_m,heading_rad");
  std::size_t rows = 0;
  while (std::getline(lines, line)) ++rows;
  EXPECT_EQ(rows, 50U * 2U);  // 5 s of 0.1 s steps, two objects
  EXPECT_NE(objects.find("\n0,0,0,100,100,0\n"), std::string::npos) << objects.substr(0, 200);
  EXPECT_NE(objects.find("\n49,4900000000,1,"), std::string::npos);
}

TEST(OdeRun, Kinematic2dRefusesObjects) {
  TempDir dir;
  const auto result = run_swarmnet("run " + kOdeScenario + " --set duration_s=5 --quiet --out " +
                                   (dir.path() / "run").string() + kObjects +
                                   " --set physics.plugin=kinematic2d --set physics.params={}");
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.output.find("kinematic2d: the arena has 2 movable object(s) (arena.objects)"),
            std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace swarmnet::testing
