#include "outputs/object_trace.hpp"

#include "text/shortest_number.hpp"

namespace swarmnet {

ObjectTraceWriter::ObjectTraceWriter(std::ostream& out, SimTime step) : out_(out), step_(step) {
  out_ << "step,time_ns,object,x_m,y_m,heading_rad\n";
}

void ObjectTraceWriter::sample(std::uint64_t step_index, std::span<const ObjectPose> poses) {
  const std::int64_t time_ns = step_.count() * static_cast<std::int64_t>(step_index);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    out_ << step_index << ',' << time_ns << ',' << i << ',';
    write_shortest(out_, poses[i].position.x());
    out_ << ',';
    write_shortest(out_, poses[i].position.y());
    out_ << ',';
    write_shortest(out_, poses[i].heading_rad);
    out_ << '\n';
  }
}

}  // namespace swarmnet
