// What plugins show the viewer: only changes are kept, and view_states.csv says them exactly.
#include "robot/view_record.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace swarmnet {
namespace {

std::string csv(const ViewRecord& record) {
  std::ostringstream out;
  record.write_csv(out);
  return out.str();
}

TEST(ViewRecord, KeepsOnlyChangesOfARobotsState) {
  ViewRecord record(3);
  record.robot_state(SimTime(0), 1, "exploring");
  record.robot_state(SimTime(100), 1, "exploring");  // unchanged: no row
  record.robot_state(SimTime(200), 2, "going");
  record.robot_state(SimTime(300), 1, "waiting");
  record.robot_state(SimTime(400), 1, "");  // cleared
  EXPECT_EQ(record.rows(), 4U);
  EXPECT_EQ(csv(record),
            "time_ns,entity,id,kind,state,x_m,y_m,radius_m\n"
            "0,robot,1,,exploring,,,\n"
            "200,robot,2,,going,,,\n"
            "300,robot,1,,waiting,,,\n"
            "400,robot,1,,,,,\n");
}

TEST(ViewRecord, ObjectsChangeWithStateOrPlaceAndCanBeHidden) {
  ViewRecord record(1);
  EXPECT_TRUE(record.empty());
  record.object(SimTime(0), 7, "event", "unserviced", Vec2(1.5, 2.0), 5.0);
  record.object(SimTime(100), 7, "event", "unserviced", Vec2(1.5, 2.0), 5.0);  // same: no row
  record.object(SimTime(200), 7, "event", "being serviced", Vec2(1.5, 2.0), 5.0);
  record.object(SimTime(300), 7, "event", "being serviced", Vec2(0.1, 2.0), 5.0);  // moved
  record.hide(SimTime(400), 7);
  record.hide(SimTime(500), 7);  // hidden already: no row
  EXPECT_EQ(csv(record),
            "time_ns,entity,id,kind,state,x_m,y_m,radius_m\n"
            "0,object,7,event,unserviced,1.5,2,5\n"
            "200,object,7,event,being serviced,1.5,2,5\n"
            "300,object,7,event,being serviced,0.1,2,5\n"
            "400,hidden,7,,,,,\n");
}

TEST(ViewRecord, LabelsStayOneCsvField) {
  ViewRecord record(1);
  record.robot_state(SimTime(0), 0, "a,b\n\"c\"");
  record.robot_state(SimTime(1), 0, "a_b__c_");  // the same label once made safe: no row
  EXPECT_EQ(csv(record), "time_ns,entity,id,kind,state,x_m,y_m,radius_m\n0,robot,0,,a_b__c_,,,\n");
}

}  // namespace
}  // namespace swarmnet
