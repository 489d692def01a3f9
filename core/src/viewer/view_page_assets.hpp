// The viewer page's files (core/src/viewer/page/), compiled into the command by embed_page.cmake.
#pragma once

#include <string_view>

namespace swarmnet {

extern const std::string_view kViewPageHtml;    // page/viewer.html: the template
extern const std::string_view kViewPageScript;  // page/viewer.js
extern const std::string_view kViewPageStyle;   // page/viewer.css

}  // namespace swarmnet
