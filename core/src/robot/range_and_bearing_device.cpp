#include "robot/range_and_bearing_device.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "swarmnet/proximity_ring.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr std::uint64_t kStreamKey = hash_name("range_and_bearing");
// Widens every disc's angular half-width so that a line grazing a disc is still tested against
// it despite rounding in the bin arithmetic; ray_to_disc() decides.
constexpr double kAngleMarginRad = 1e-9;
// Direction bins per receiver: about one per nearby robot, within these bounds.
constexpr std::size_t kMinBins = 16;
constexpr std::size_t kMaxBins = 4096;

// `angle_rad` in (-pi, pi].
double wrapped(double angle_rad) {
  double a = std::remainder(angle_rad, kTwoPi);
  if (a <= -std::numbers::pi) a += kTwoPi;
  return a;
}

// Bin `k` of `bins`, counting around the circle.
std::size_t bin_index(std::int64_t k, std::int64_t bins) {
  return static_cast<std::size_t>(((k % bins) + bins) % bins);
}

// The bin (not yet taken modulo the bin count) of direction `direction_rad` in [-pi, pi].
std::int64_t bin_of(double direction_rad, double bin_rad) {
  return static_cast<std::int64_t>(std::floor((direction_rad + std::numbers::pi) / bin_rad));
}

}  // namespace

RangeAndBearingDevice::RangeAndBearingDevice(const RangeAndBearingConfig& config,
                                             std::size_t robots, std::uint64_t seed)
    : config_(config),
      seed_(seed),
      emitted_(robots * config.data_bytes, std::byte{0}),
      sensed_(emitted_),
      first_(robots + 1, 0) {}

void RangeAndBearingDevice::set_data(RobotId robot, std::span<const std::byte> data) {
  const std::size_t bytes = config_.data_bytes;
  if (data.size() > bytes) {
    throw std::invalid_argument("robot " + std::to_string(robot) +
                                ": set_range_and_bearing_data(): " + std::to_string(data.size()) +
                                " bytes is more than an emitter carries, " + std::to_string(bytes) +
                                " (robots.range_and_bearing.data_bytes)");
  }
  const auto slot = emitted_.begin() + static_cast<std::ptrdiff_t>(robot * bytes);
  std::copy(data.begin(), data.end(), slot);
  std::fill(slot + static_cast<std::ptrdiff_t>(data.size()),
            slot + static_cast<std::ptrdiff_t>(bytes), std::byte{0});
}

std::span<const RangeAndBearingReading> RangeAndBearingDevice::readings(RobotId robot) const {
  return {readings_.data() + first_[robot], first_[robot + 1] - first_[robot]};
}

void RangeAndBearingDevice::sense(const Arena& arena, std::span<const RobotBody> bodies,
                                  std::span<const ObjectPose> object_poses,
                                  std::span<const std::uint8_t> switched_off, std::uint64_t step) {
  std::copy(emitted_.begin(), emitted_.end(), sensed_.begin());
  readings_.clear();
  const std::size_t robots = std::min(bodies.size(), first_.size() - 1);
  double max_radius_m = 0.0;
  positions_.resize(robots);
  for (std::size_t r = 0; r < robots; ++r) {
    positions_[r] = bodies[r].position;
    max_radius_m = std::max(max_radius_m, bodies[r].radius_m);
  }
  // A cell of about the query radius: each receiver visits a few cells.
  const Rect bounds{0.0, 0.0, arena.width_m, arena.height_m};
  const double cell_m = config_.range_m + max_radius_m;
  if (!(bounds == grid_bounds_) || cell_m != grid_cell_m_) {
    grid_.reset(bounds, cell_m);
    grid_bounds_ = bounds;
    grid_cell_m_ = cell_m;
  }
  grid_.build(positions_);
  for (std::size_t r = 0; r < robots; ++r) {
    first_[r] = readings_.size();
    if (r < switched_off.size() && switched_off[r] == 1) continue;
    sense_receiver(arena, bodies.first(robots), object_poses, switched_off, r, max_radius_m, step);
  }
  std::fill(first_.begin() + static_cast<std::ptrdiff_t>(robots), first_.end(), readings_.size());
}

void RangeAndBearingDevice::sense_receiver(const Arena& arena, std::span<const RobotBody> bodies,
                                           std::span<const ObjectPose> object_poses,
                                           std::span<const std::uint8_t> switched_off,
                                           std::size_t receiver, double max_radius_m,
                                           std::uint64_t step) {
  const Vec2& origin = bodies[receiver].position;
  const double range_m = config_.range_m;
  nearby_.clear();
  bool any_emitter = false;
  // Every disc that can cross a line of at most range_m from the centre has its centre within
  // range_m + max_radius_m of it.
  grid_.for_each_candidate(origin, range_m + max_radius_m, [&](std::uint32_t j) {
    if (j == receiver) return;
    const Vec2 offset = bodies[j].position - origin;
    const double distance_m = offset.norm();
    const bool on = j >= switched_off.size() || switched_off[j] != 1;
    const bool emits = on && distance_m <= range_m && distance_m > 0.0;
    if (!emits && distance_m - bodies[j].radius_m >= range_m) return;  // neither seen nor between
    any_emitter = any_emitter || emits;
    Nearby& near = nearby_.emplace_back();
    near.robot = j;
    near.offset = offset;
    near.distance_m = distance_m;
    near.direction_rad = std::atan2(offset.y(), offset.x());
    near.emits = emits;
  });
  if (!any_emitter) return;

  near_obstacles_.clear();
  for (std::size_t i = 0; i < arena.obstacles.size(); ++i) {
    if (distance_to_rect(arena.obstacles[i], origin) <= range_m) near_obstacles_.push_back(i);
  }
  near_objects_.clear();
  for (std::size_t o = 0; o < object_poses.size() && o < arena.objects.size(); ++o) {
    const double centre_m = (object_poses[o].position - origin).norm();
    if (centre_m - object_reach_m(arena.objects[o]) <= range_m) near_objects_.push_back(o);
  }
  bin_discs(bodies);

  seen_.clear();
  for (std::uint32_t i = 0; i < nearby_.size(); ++i) {
    if (nearby_[i].emits && !blocked(arena, bodies, object_poses, origin, nearby_[i])) {
      seen_.push_back(i);
    }
  }
  std::sort(seen_.begin(), seen_.end(), [this](std::uint32_t a, std::uint32_t b) {
    return nearby_[a].robot < nearby_[b].robot;
  });
  for (const std::uint32_t i : seen_) {
    add_reading(receiver, nearby_[i], bodies[receiver].heading_rad, step);
  }
}

void RangeAndBearingDevice::bin_discs(std::span<const RobotBody> bodies) {
  bins_ = std::clamp(std::bit_ceil(nearby_.size()), kMinBins, kMaxBins);
  const auto bins = static_cast<std::int64_t>(bins_);
  const double bin_rad = kTwoPi / static_cast<double>(bins_);
  for (Nearby& near : nearby_) {
    const double radius_m = bodies[near.robot].radius_m;
    near.first_bin = 0;
    near.last_bin = bins - 1;
    if (near.distance_m <= radius_m) continue;  // the receiver is inside it: every direction
    const double half_width_rad = std::asin(radius_m / near.distance_m) + kAngleMarginRad;
    const std::int64_t first = bin_of(near.direction_rad - half_width_rad, bin_rad);
    const std::int64_t last = bin_of(near.direction_rad + half_width_rad, bin_rad);
    if (last - first + 1 < bins) {
      near.first_bin = first;
      near.last_bin = last;
    }
  }
  // Counting sort of the discs into the bins they cover.
  bin_start_.assign(bins_ + 1, 0);
  for (const Nearby& near : nearby_) {
    for (std::int64_t k = near.first_bin; k <= near.last_bin; ++k) {
      ++bin_start_[bin_index(k, bins) + 1];
    }
  }
  for (std::size_t b = 1; b <= bins_; ++b) bin_start_[b] += bin_start_[b - 1];
  bin_entries_.resize(bin_start_[bins_]);
  bin_fill_.assign(bin_start_.begin(), bin_start_.end() - 1);
  for (std::uint32_t i = 0; i < nearby_.size(); ++i) {
    for (std::int64_t k = nearby_[i].first_bin; k <= nearby_[i].last_bin; ++k) {
      bin_entries_[bin_fill_[bin_index(k, bins)]++] = i;
    }
  }
}

bool RangeAndBearingDevice::blocked(const Arena& arena, std::span<const RobotBody> bodies,
                                    std::span<const ObjectPose> object_poses, const Vec2& origin,
                                    const Nearby& emitter) const {
  const Vec2 u = emitter.offset / emitter.distance_m;
  const double distance_m = emitter.distance_m;
  for (const std::size_t i : near_obstacles_) {
    if (ray_to_rect(arena.obstacles[i], origin, u) < distance_m) return true;
  }
  for (const std::size_t o : near_objects_) {
    if (ray_to_object(arena.objects[o], object_poses[o], origin, u) < distance_m) return true;
  }
  // A disc the line crosses covers the line's direction, so it is in that direction's bin.
  const auto bins = static_cast<std::int64_t>(bins_);
  const std::size_t bin =
      bin_index(bin_of(emitter.direction_rad, kTwoPi / static_cast<double>(bins_)), bins);
  for (std::uint32_t k = bin_start_[bin]; k < bin_start_[bin + 1]; ++k) {
    const Nearby& other = nearby_[bin_entries_[k]];
    if (other.robot == emitter.robot) continue;
    const RobotBody& body = bodies[other.robot];
    if (ray_to_disc(body.position, body.radius_m, origin, u) < distance_m) return true;
  }
  return false;
}

void RangeAndBearingDevice::add_reading(std::size_t receiver, const Nearby& emitter,
                                        double heading_rad, std::uint64_t step) {
  double range_m = emitter.distance_m;
  double bearing_rad = wrapped(emitter.direction_rad - heading_rad);
  if (config_.loss_probability > 0.0 || config_.range_noise_sd_m > 0.0 ||
      config_.bearing_noise_sd_rad > 0.0) {
    RandomStream stream(derive_seed(seed_, {kStreamKey, receiver, emitter.robot, step}));
    if (config_.loss_probability > 0.0 && stream.bernoulli(config_.loss_probability)) return;
    if (config_.range_noise_sd_m > 0.0) {
      range_m = std::max(0.0, stream.normal(range_m, config_.range_noise_sd_m));
    }
    if (config_.bearing_noise_sd_rad > 0.0) {
      bearing_rad = wrapped(stream.normal(bearing_rad, config_.bearing_noise_sd_rad));
    }
  }
  const std::size_t bytes = config_.data_bytes;
  readings_.push_back(RangeAndBearingReading{
      emitter.robot, range_m, bearing_rad,
      std::span<const std::byte>(sensed_.data() + emitter.robot * bytes, bytes)});
}

}  // namespace swarmnet
