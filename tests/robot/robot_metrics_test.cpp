#include "robot/robot_metrics.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

namespace swarmnet {
namespace {

TEST(RobotMetrics, CsvHasOneRowPerRobotAndMetricItRecorded) {
  RobotMetrics metrics(3);
  metrics.add(2, "b", 1.5);
  metrics.add(0, "b", 4.0);
  metrics.add(0, "a", -2.0);
  metrics.add(0, "a", 1.0);
  metrics.add(2, "with,comma \"q\"", 0.1);
  std::ostringstream out;
  metrics.write_csv(out);
  EXPECT_EQ(out.str(),
            "robot,metric,count,sum,mean,min,max\n"
            "0,a,2,-1,-0.5,-2,1\n"
            "0,b,1,4,4,4,4\n"
            "2,b,1,1.5,1.5,1.5,1.5\n"
            "2,\"with,comma \"\"q\"\"\",1,0.1,0.1,0.1,0.1\n");
}

TEST(RobotMetrics, PooledEqualsTheSumOverRobots) {
  RobotMetrics metrics(4);
  for (RobotId robot = 0; robot < 4; ++robot) {
    for (int k = 0; k <= static_cast<int>(robot); ++k) metrics.add(robot, "m", robot + 0.5 * k);
  }
  const ControllerMetrics pooled = metrics.pooled();
  std::uint64_t count = 0;
  double sum = 0.0;
  for (RobotId robot = 0; robot < 4; ++robot) {
    count += metrics.of(robot, "m").count;
    sum += metrics.of(robot, "m").sum;
  }
  EXPECT_EQ(pooled.at("m").count, count);
  EXPECT_DOUBLE_EQ(pooled.at("m").sum, sum);
  EXPECT_EQ(pooled.at("m").min, 0.0);
  EXPECT_EQ(pooled.at("m").max, 4.5);
}

TEST(RobotMetrics, EmptyUntilRecordedAndRefusesAnUnknownRobot) {
  RobotMetrics metrics(2);
  EXPECT_TRUE(metrics.empty());
  EXPECT_THROW(metrics.add(2, "m", 1.0), std::out_of_range);
  metrics.add(1, "m", 1.0);
  EXPECT_FALSE(metrics.empty());
}

}  // namespace
}  // namespace swarmnet
