#include "scenario/free_area.hpp"

#include <algorithm>
#include <utility>

namespace swarmnet {

double free_area(const Rect& region, const std::vector<Rect>& obstacles) {
  // Clip to the region, then sweep along x: in each slab between consecutive x edges, the covered
  // length is the union of the y intervals of the obstacles spanning it.
  std::vector<Rect> clipped;
  std::vector<double> xs{region.x_min_m, region.x_max_m};
  for (const auto& obstacle : obstacles) {
    const Rect r{
        std::max(obstacle.x_min_m, region.x_min_m), std::max(obstacle.y_min_m, region.y_min_m),
        std::min(obstacle.x_max_m, region.x_max_m), std::min(obstacle.y_max_m, region.y_max_m)};
    if (r.x_min_m >= r.x_max_m || r.y_min_m >= r.y_max_m) continue;
    clipped.push_back(r);
    xs.push_back(r.x_min_m);
    xs.push_back(r.x_max_m);
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());

  double covered = 0.0;
  std::vector<std::pair<double, double>> spans;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    spans.clear();
    for (const auto& r : clipped) {
      if (r.x_min_m <= xs[i] && r.x_max_m >= xs[i + 1]) spans.emplace_back(r.y_min_m, r.y_max_m);
    }
    std::sort(spans.begin(), spans.end());
    double length = 0.0;
    double start = 0.0;
    double end = 0.0;
    bool open = false;
    for (const auto& [low, high] : spans) {
      if (!open || low > end) {
        if (open) length += end - start;
        start = low;
        end = high;
        open = true;
      } else {
        end = std::max(end, high);
      }
    }
    if (open) length += end - start;
    covered += length * (xs[i + 1] - xs[i]);
  }
  return region.width_m() * region.height_m() - covered;
}

}  // namespace swarmnet
