// Every robot's range-and-bearing device (swarmnet/range_and_bearing.hpp): the data each emitter
// carries, and what each receiver saw when the device last sensed. A line-of-sight device of the
// robot half: it knows nothing of the radio or the network half.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "robot/robot_settings.hpp"
#include "swarmnet/arena.hpp"
#include "swarmnet/physics.hpp"
#include "swarmnet/range_and_bearing.hpp"
#include "swarmnet/robot_body.hpp"
#include "swarmnet/spatial_grid.hpp"

namespace swarmnet {

class RangeAndBearingDevice {
 public:
  // For `robots` robots, every emitter carrying zeros. `config` is valid (the scenario checks
  // it: range_m > 0, noise >= 0, loss_probability in [0, 1], data_bytes at most
  // kMaxRangeAndBearingDataBytes); `seed` is the scenario's master seed (see sense()).
  RangeAndBearingDevice(const RangeAndBearingConfig& config, std::size_t robots,
                        std::uint64_t seed);

  // What robot `robot`'s emitter carries from the next sense() on: `data`, zero-padded to the
  // configured size. Throws std::invalid_argument for more bytes than that.
  void set_data(RobotId robot, std::span<const std::byte> data);

  // Makes every robot's readings for step `step` from the bodies as they are now and the data
  // every emitter carries now. Receiver r sees emitter e (another robot) when their centres are
  // at most range_m apart and the segment between them crosses no obstacle of `arena`, no
  // movable object (arena.objects[i] at object_poses[i]) and no other robot's disc. A robot with
  // switched_off[r] == 1 neither emits nor receives; its body still blocks. Noise and loss of
  // the reading of e at r in step k draw from a stream of their own,
  // derive_seed(seed, {hash_name("range_and_bearing"), r, e, k}), so no reading depends on
  // another or on the order robots are visited in. Candidates come from a uniform grid, and
  // only the robots within a small angle of a line are tested against it, so the cost is about
  // robots x (neighbours within range + obstacles near the robot), not robots squared.
  void sense(const Arena& arena, std::span<const RobotBody> bodies,
             std::span<const ObjectPose> object_poses, std::span<const std::uint8_t> switched_off,
             std::uint64_t step);

  // Robot `robot`'s readings from the last sense(), ascending by emitter id; their data stays
  // valid until the next sense().
  [[nodiscard]] std::span<const RangeAndBearingReading> readings(RobotId robot) const;

 private:
  // A robot near the receiver being sensed: an emitter it may see, a disc that may block, or
  // both. Bins first_bin..last_bin (modulo the bin count, all of them from inside the disc) are
  // the directions the disc covers.
  struct Nearby {
    RobotId robot = 0;
    Vec2 offset = Vec2::Zero();  // from the receiver's centre
    double distance_m = 0.0;
    double direction_rad = 0.0;  // of the offset, from +x
    bool emits = false;          // within range and switched on
    std::int64_t first_bin = 0;
    std::int64_t last_bin = 0;
  };

  void sense_receiver(const Arena& arena, std::span<const RobotBody> bodies,
                      std::span<const ObjectPose> object_poses,
                      std::span<const std::uint8_t> switched_off, std::size_t receiver,
                      double max_radius_m, std::uint64_t step);
  // Sorts the nearby discs into direction bins (bins_, bin_entries_).
  void bin_discs(std::span<const RobotBody> bodies);
  [[nodiscard]] bool blocked(const Arena& arena, std::span<const RobotBody> bodies,
                             std::span<const ObjectPose> object_poses, const Vec2& origin,
                             const Nearby& emitter) const;
  void add_reading(std::size_t receiver, const Nearby& emitter, double heading_rad,
                   std::uint64_t step);

  RangeAndBearingConfig config_;
  std::uint64_t seed_;
  std::vector<std::byte> emitted_;  // data_bytes per robot: what set_data() set
  std::vector<std::byte> sensed_;   // emitted_ as of the last sense(): what readings show
  std::vector<RangeAndBearingReading> readings_;
  std::vector<std::size_t> first_;  // robot r's readings are [first_[r], first_[r + 1])

  // Scratch space, kept from call to call so that sensing allocates nothing once warmed up.
  std::vector<Vec2> positions_;
  SpatialGrid grid_;
  Rect grid_bounds_;
  double grid_cell_m_ = 0.0;
  std::vector<Nearby> nearby_;
  std::vector<std::size_t> near_obstacles_;  // of the receiver being sensed
  std::vector<std::size_t> near_objects_;
  std::vector<std::uint32_t> bin_start_;  // bin b holds bin_entries_[bin_start_[b], [b + 1])
  std::vector<std::uint32_t> bin_fill_;
  std::vector<std::uint32_t> bin_entries_;  // indices into nearby_
  std::size_t bins_ = 0;
  std::vector<std::uint32_t> seen_;  // indices into nearby_ of the emitters seen
};

}  // namespace swarmnet
