#include "plugin/plugin_catalog.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <system_error>
#include <vector>

#include "text/text_join.hpp"

namespace swarmnet {

namespace {

// Columns padded to their widest cell, two spaces apart; the last column is not padded.
class TextTable {
 public:
  explicit TextTable(std::vector<std::string> header) { rows_.push_back(std::move(header)); }
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }

  void print(std::ostream& out, const std::string& indent) const {
    std::vector<std::size_t> widths;
    for (const auto& row : rows_) {
      widths.resize(std::max(widths.size(), row.size()), 0);
      for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
    }
    for (const auto& row : rows_) {
      std::string line = indent;
      for (std::size_t c = 0; c < row.size(); ++c) {
        line += row[c];
        if (c + 1 < row.size()) line += std::string(widths[c] - row[c].size() + 2, ' ');
      }
      while (!line.empty() && line.back() == ' ') line.pop_back();
      out << line << '\n';
    }
  }

 private:
  std::vector<std::vector<std::string>> rows_;
};

std::string or_dash(const std::string& text) { return text.empty() ? "-" : text; }

// Integer parameters store their bounds as doubles; the int64 extremes mean "no bound".
constexpr double kIntegerLimit = 9.2e18;

}  // namespace

std::string format_real(double value) {
  char buffer[64];
  const double magnitude = std::fabs(value);
  const bool fixed = magnitude == 0.0 || (magnitude >= 1e-4 && magnitude < 1e15);
  const auto result =
      fixed ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
            : std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
  if (result.ec != std::errc()) return std::to_string(value);
  return std::string(buffer, result.ptr);
}

std::string format_param_value(const ParamValue& value) {
  if (const auto* real = std::get_if<double>(&value)) return format_real(*real);
  if (const auto* integer = std::get_if<std::int64_t>(&value)) return std::to_string(*integer);
  if (const auto* boolean = std::get_if<bool>(&value)) return *boolean ? "true" : "false";
  return std::get<std::string>(value);
}

std::string format_param_range(const ParamSpec& spec) {
  if (spec.type != ParamType::real && spec.type != ParamType::integer) return "";
  const bool integer = spec.type == ParamType::integer;
  const bool has_min = std::isfinite(spec.min) && !(integer && spec.min <= -kIntegerLimit);
  const bool has_max = std::isfinite(spec.max) && !(integer && spec.max >= kIntegerLimit);
  const auto bound = [integer](double v) {
    return integer ? std::to_string(static_cast<std::int64_t>(v)) : format_real(v);
  };
  if (has_min && has_max) return bound(spec.min) + ".." + bound(spec.max);
  if (has_min) return ">= " + bound(spec.min);
  if (has_max) return "<= " + bound(spec.max);
  return "any";
}

void print_plugin_table(std::ostream& out, PluginLoader& loader) {
  std::vector<BrokenPlugin> broken;
  const auto libraries = loader.discover(&broken);
  if (libraries.empty()) {
    out << "No plugins found.\n";
  } else {
    TextTable table({"KIND", "NAME", "VERSION", "PATH", "SUMMARY"});
    for (const auto& library : libraries) {
      const auto& info = library->info();
      table.add({to_string(library->kind()), info.name, or_dash(info.version),
                 library->path().string(), or_dash(info.summary)});
    }
    table.print(out, "");
  }
  if (!broken.empty()) {
    out << "\nBroken plugin files (not loaded):\n";
    for (const auto& file : broken) {
      // The loader's errors name the file already; name it once.
      const bool named = file.error.find(file.path.string()) != std::string::npos;
      out << "  " << (named ? "" : file.path.string() + ": ") << file.error << '\n';
    }
  }
  out << "\nSearch path, in order:\n";
  std::size_t position = 1;
  for (const auto& dir : loader.search_path()) {
    std::error_code ec;
    const bool exists = std::filesystem::is_directory(dir, ec);
    out << "  " << position++ << ". " << dir.string() << (exists ? "" : "  (does not exist)")
        << '\n';
  }
}

void print_plugin_details(std::ostream& out, const PluginLibrary& library) {
  const auto& info = library.info();
  TextTable facts({"name:", info.name});
  facts.add({"kind:", to_string(library.kind())});
  facts.add({"version:", or_dash(info.version)});
  facts.add({"path:", library.path().string()});
  facts.add({"summary:", or_dash(info.summary)});
  facts.print(out, "");
  if (!info.description.empty()) {
    out << '\n' << info.description;
    if (info.description.back() != '\n') out << '\n';
  }
  out << '\n';
  if (info.params.empty()) {
    out << "Parameters: none\n";
    return;
  }
  out << "Parameters (set under params: in the scenario):\n";
  TextTable table({"NAME", "TYPE", "DEFAULT", "RANGE", "UNIT", "CHOICES", "HELP"});
  for (const auto& spec : info.params) {
    std::string default_text = format_param_value(spec.default_value);
    if (spec.type == ParamType::text) default_text = '"' + std::move(default_text) + '"';
    table.add({spec.name, to_string(spec.type), default_text, or_dash(format_param_range(spec)),
               or_dash(spec.unit), or_dash(join(spec.choices, ", ")), spec.help});
  }
  table.print(out, "  ");
}

}  // namespace swarmnet
