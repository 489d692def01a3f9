// Short names for the values of one `stats --by` column, for its tables and for --baseline.
//
// A grid over a plugin choice writes whole YAML mappings into results.csv
// (`{plugin: flooding, params: {ttl: 32, jitter_max_s: 0.005}}`). Such a value is named by its
// `plugin` entry, followed by `key=value` for each entry whose value differs between the
// column's values, so that two settings of one plugin stay apart (`flooding ttl=16`,
// `flooding ttl=32`) and what is the same everywhere is not repeated. Entries under `params` are
// named by their key (`ttl`), others by their path (`mac.plugin`). A mapping without `plugin` is
// named by those `key=value` alone, or all of its entries when none differs. Any other value
// (a number, a word) is its own name. Should two values still get one name, both keep their text.
#pragma once

#include <string>
#include <vector>

namespace swarmnet {

// One name per value, in the order given; equal values get equal names.
std::vector<std::string> short_labels(const std::vector<std::string>& values);

}  // namespace swarmnet
