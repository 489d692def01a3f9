#include "viewer/view_page.hpp"

#include <array>

#include "outputs/atomic_file.hpp"
#include "viewer/view_page_assets.hpp"

namespace swarmnet {

namespace {

// Replaces the first occurrence of `marker` in `page` at or after `from`; returns where the text
// put in ends, so that no filled-in text is searched for a later marker.
std::size_t fill(std::string& page, std::size_t from, std::string_view marker,
                 std::string_view text) {
  const std::size_t at = page.find(marker, from);
  if (at == std::string::npos) return from;
  page.replace(at, marker.size(), text);
  return at + text.size();
}

// JSON text safe inside <script>: "</" becomes "<\/", an equivalent JSON string escape.
std::string script_safe(std::string json) {
  for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at + 3)) {
    json.insert(at + 1, "\\");
  }
  return json;
}

std::string html_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string base64_encode(const std::uint8_t* data, std::size_t size) {
  static constexpr std::string_view kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < size; i += 3) {
    const std::uint32_t v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i < size) {
    const std::uint32_t v = (data[i] << 16) | (i + 1 < size ? data[i + 1] << 8 : 0);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < size ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string render_view_page(const ViewData& data) {
  const std::string blob = base64_encode(data.blob.data(), data.blob.size());
  std::string page(kViewPageHtml);
  page.reserve(page.size() + blob.size() + kViewPageScript.size() + kViewPageStyle.size() + 4096);
  // In the order they appear in the template.
  std::size_t at =
      fill(page, 0, "@TITLE@", html_escaped(data.meta.value("name", std::string("run"))));
  at = fill(page, at, "@CSS@", kViewPageStyle);
  at = fill(page, at, "@META@", script_safe(data.meta.dump()));
  at = fill(page, at, "@BLOB@", blob);
  fill(page, at, "@JS@", kViewPageScript);
  return page;
}

void write_view_page(const std::filesystem::path& run_dir, const std::filesystem::path& out,
                     const ViewLimits& limits) {
  const std::string page = render_view_page(read_view_data(run_dir, limits));
  AtomicFile file(out);
  file.stream() << page;
  file.commit();
}

}  // namespace swarmnet
