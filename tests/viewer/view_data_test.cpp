// The viewer's reading of a run directory: what it packs, and a clear error naming the file for
// every missing, truncated or malformed one (never a page that draws nothing).
#include "viewer/view_data.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "outputs/headings_trace.hpp"
#include "outputs/positions_trace.hpp"
#include "outputs/run_error.hpp"
#include "viewer/frame_renderer.hpp"
#include "viewer/view_page.hpp"

namespace swarmnet {
namespace {

namespace fs = std::filesystem;

class RunDirectory : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "swarmnet-view-test-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    write("scenario.resolved.yaml",
          "name: tiny\nstep_s: 0.5\narena:\n  width_m: 100\n  height_m: 50\n  obstacles:\n"
          "    - {x_min_m: 10, y_min_m: 10, x_max_m: 20, y_max_m: 20}\nrobots:\n  radius_m: 0.5\n");
    write("summary.json", R"({"robots": 2, "pdr": 0.5})");
    std::ofstream out(dir_ / "positions.bin", std::ios::binary);
    PositionsTraceWriter writer(out, 2, 4, from_seconds(0.5));
    for (int step = 0; step < 4; ++step) {
      const std::vector<Vec2> at = {Vec2(10.0 + step, 5.0), Vec2(50.0, 25.0 + step)};
      writer.sample(at);
    }
    writer.finish();
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  // The message of the RunError reading the directory throws; "" when it reads.
  std::string error() {
    try {
      (void)read_view_data(dir_);
    } catch (const RunError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

TEST_F(RunDirectory, PacksPositionsHeadingsAndStates) {
  write("view_states.csv",
        "time_ns,entity,id,kind,state,x_m,y_m,radius_m\n"
        "0,robot,1,,going,,,\n"
        "0,object,0,event,unserviced,30,30,2\n"
        "1000000000,object,0,event,serviced,30,30,2\n");
  const ViewData data = read_view_data(dir_);
  EXPECT_EQ(data.meta["robots"], 2);
  EXPECT_EQ(data.meta["headings"], "direction of motion");  // no headings.bin
  EXPECT_EQ(data.meta["frames"], 4);
  EXPECT_DOUBLE_EQ(data.meta["duration_s"].get<double>(), 2.0);
  EXPECT_EQ(data.meta["states"], (std::vector<std::string>{"", "going", "unserviced", "serviced"}));
  const auto pos = data.meta["arrays"]["pos"];
  ASSERT_EQ(pos[1], 4 * 2 * 2);
  const auto* q =
      reinterpret_cast<const std::uint16_t*>(data.blob.data() + pos[0].get<std::size_t>());
  EXPECT_EQ(q[0], static_cast<std::uint16_t>(std::lround(10.0 / 100.0 * 65535)));  // robot 0 x
  EXPECT_EQ(q[3], static_cast<std::uint16_t>(std::lround(25.0 / 50.0 * 65535)));   // robot 1 y
  const auto heading = data.meta["arrays"]["heading"];
  const std::uint8_t* h = data.blob.data() + heading[0].get<std::size_t>();
  EXPECT_EQ(h[2 * 2 + 0], 0);   // robot 0 moves along +x
  EXPECT_EQ(h[2 * 2 + 1], 64);  // robot 1 along +y: a quarter turn
  const auto state = data.meta["arrays"]["state"];
  EXPECT_EQ(data.blob[state[0].get<std::size_t>() + 1], 1);  // robot 1 "going" from t = 0
  EXPECT_EQ(data.meta["arrays"]["obj_t"][1], 2);
}

TEST_F(RunDirectory, HeadingsComeFromHeadingsBinWhenTheRunWroteIt) {
  {
    std::ofstream out(dir_ / "headings.bin", std::ios::binary);
    HeadingsTraceWriter writer(out, 2, 4, from_seconds(0.5));
    std::vector<RobotBody> bodies(2);
    for (int step = 0; step < 4; ++step) {
      bodies[0].heading_rad = std::numbers::pi;  // turning on the spot would not show in x, y
      bodies[1].heading_rad = -std::numbers::pi / 2;
      writer.sample(bodies);
    }
  }
  const ViewData data = read_view_data(dir_);
  EXPECT_EQ(data.meta["headings"], "recorded");
  const std::uint8_t* h = data.blob.data() + data.meta["arrays"]["heading"][0].get<std::size_t>();
  EXPECT_EQ(h[2 * 2 + 0], 128);  // half a turn
  EXPECT_EQ(h[2 * 2 + 1], 192);  // three quarters

  fs::resize_file(dir_ / "headings.bin", 32 + 7);
  EXPECT_NE(error().find("headings.bin: is 39 bytes long"), std::string::npos) << error();
}

TEST(HeadingsTrace, QuantizesToTurnsCounterClockwiseFromX) {
  EXPECT_EQ(quantize_heading(0.0), 0);
  EXPECT_EQ(quantize_heading(std::numbers::pi / 2), 64);
  EXPECT_EQ(quantize_heading(-std::numbers::pi / 2), 192);
  EXPECT_EQ(quantize_heading(2 * std::numbers::pi - 1e-9), 0);  // wraps
  EXPECT_EQ(quantize_heading(std::nan("")), 0);
}

TEST_F(RunDirectory, ThePageHoldsEverythingItNeeds) {
  const std::string page = render_view_page(read_view_data(dir_));
  EXPECT_NE(page.find("<title>tiny"), std::string::npos);
  EXPECT_EQ(page.find("@META@"), std::string::npos);
  EXPECT_EQ(page.find("@BLOB@"), std::string::npos);
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(page.find("http://"), std::string::npos);
  EXPECT_EQ(page.find("https://"), std::string::npos);
}

TEST_F(RunDirectory, TruncatedPositionsNameTheFile) {
  fs::resize_file(dir_ / "positions.bin", fs::file_size(dir_ / "positions.bin") - 5);
  const std::string message = error();
  EXPECT_NE(message.find("positions.bin"), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST_F(RunDirectory, MissingFilesAreNamed) {
  fs::remove(dir_ / "summary.json");
  EXPECT_NE(error().find("summary.json: is missing"), std::string::npos) << error();
  write("summary.json", R"({"robots": 2})");
  fs::remove(dir_ / "positions.bin");
  EXPECT_NE(error().find("positions.bin: is missing"), std::string::npos) << error();
}

TEST_F(RunDirectory, MalformedFilesAreNamedWithTheLine) {
  write("summary.json", "{\"robots\": ");
  EXPECT_NE(error().find("summary.json: not valid JSON"), std::string::npos) << error();
  write("summary.json", R"({"robots": 3})");
  EXPECT_NE(error().find("positions.bin: holds 2 robots; summary.json says 3"), std::string::npos)
      << error();
  write("summary.json", R"({"robots": 2})");
  write("packets.csv",
        "time_ns,event,node,uid,message_id,source,destination,hops,bytes,detail\n"
        "100,send,0,1,1,0,1,0,40,\n"
        "200,deliver,x,1,1,0,1,1,40,\n");
  EXPECT_NE(error().find("packets.csv: line 3: node 'x' is not a number"), std::string::npos)
      << error();
  write("packets.csv", "time_ns,event\n");
  EXPECT_NE(error().find("packets.csv: line 1: unexpected header"), std::string::npos) << error();
  fs::remove(dir_ / "packets.csv");
  write("view_states.csv", "time_ns,entity,id,kind,state,x_m,y_m,radius_m\n0,robot,9,,a,,,\n");
  EXPECT_NE(error().find("view_states.csv: line 2: robot 9 is not one of the 2"), std::string::npos)
      << error();
  fs::remove(dir_ / "view_states.csv");
  write("scenario.resolved.yaml", "arena: [unclosed\n");
  EXPECT_NE(error().find("scenario.resolved.yaml: not valid YAML"), std::string::npos) << error();
}

// series.csv: each series binned over the run's 2 s (200 bins of 10 ms), mean, least and
// greatest over the robots; a world's series apart; quoted names read whole.
TEST_F(RunDirectory, SampledSeriesAreBinnedForTheChart) {
  write("series.csv",
        "time_ns,robot,series,value\n"
        "0,0,\"link, \"\"share\"\"\",0.25\n"
        "0,1,\"link, \"\"share\"\"\",0.75\n"
        "1000000000,1,\"link, \"\"share\"\"\",1\n"
        "1500000000,,done,3\n");
  const ViewData view = read_view_data(dir_);
  const auto& series = view.meta.at("series");
  EXPECT_DOUBLE_EQ(series.at("bin_s").get<double>(), 0.01);
  ASSERT_EQ(series.at("series").size(), 2U);
  const auto& done = series.at("series")[0];
  EXPECT_EQ(done.at("name"), "done (world)");
  EXPECT_EQ(done.at("mean")[150], 3.0);
  EXPECT_TRUE(done.at("mean")[0].is_null());
  const auto& link = series.at("series")[1];
  EXPECT_EQ(link.at("name"), "link, \"share\"");
  EXPECT_EQ(link.at("mean")[0], 0.5);
  EXPECT_EQ(link.at("low")[0], 0.25);
  EXPECT_EQ(link.at("high")[0], 0.75);
  EXPECT_EQ(link.at("mean")[100], 1.0);
  EXPECT_EQ(series.at("not_shown"), 0U);

  write("series.csv", "time_ns,robot,series,value\n0,0,a,x\n");
  EXPECT_NE(error().find("series.csv: line 2: value 'x' is not a number"), std::string::npos)
      << error();
  write("series.csv", "time,robot\n");
  EXPECT_NE(error().find("series.csv: line 1: unexpected header"), std::string::npos) << error();
}

TEST_F(RunDirectory, PacketEventsInferThePreviousHop) {
  write("packets.csv",
        "time_ns,event,node,uid,message_id,source,destination,hops,bytes,detail\n"
        "100,send,0,1,1,0,1,0,40,\n"
        "200,forward,1,1,1,0,1,1,40,\n"
        "300,drop,1,1,1,0,1,1,40,queue_full\n"
        "400,deliver,1,1,1,0,1,1,40,\n");
  const ViewData data = read_view_data(dir_);
  EXPECT_EQ(data.meta["events"]["reasons"], (std::vector<std::string>{"queue_full"}));
  const auto from = data.meta["arrays"]["ev_from"];
  ASSERT_EQ(from[1], 4);
  const auto* f =
      reinterpret_cast<const std::uint32_t*>(data.blob.data() + from[0].get<std::size_t>());
  EXPECT_EQ(f[1], 0U);  // the forward at robot 1 came from robot 0
  EXPECT_EQ(data.meta["panel"]["delivery_ratio"][0], 1.0);
}

TEST(Base64, RoundTrips) {
  for (const std::string text : {"", "a", "ab", "abc", "abcd", "\xff\x00\x10 binary"}) {
    const std::string encoded =
        base64_encode(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    EXPECT_EQ(encoded.size() % 4, 0U);
    EXPECT_EQ(base64_decode(encoded), text);
  }
  EXPECT_EQ(base64_encode(reinterpret_cast<const std::uint8_t*>("Man"), 3), "TWFu");
}

}  // namespace
}  // namespace swarmnet
