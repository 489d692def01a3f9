# Run at build time (cmake -P): writes OUTPUT, a C++ file holding the viewer page's template,
# script and style (page/) as string constants, so that the `swarmnet` command carries them.
#   cmake -DPAGE_DIR=... -DOUTPUT=... -P embed_page.cmake
set(text "// Generated from core/src/viewer/page/ by embed_page.cmake; do not edit.\n")
string(APPEND text "#include \"viewer/view_page_assets.hpp\"\n\nnamespace swarmnet {\n\n")
foreach(pair "kViewPageHtml;viewer.html" "kViewPageScript;viewer.js" "kViewPageStyle;viewer.css")
  list(GET pair 0 name)
  list(GET pair 1 file)
  file(READ ${PAGE_DIR}/${file} content)
  string(FIND "${content}" ")swarmnet_page\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${file} contains the raw-string delimiter )swarmnet_page\"")
  endif()
  string(APPEND text "const std::string_view ${name} = R\"swarmnet_page(${content})swarmnet_page\";\n\n")
endforeach()
string(APPEND text "}  // namespace swarmnet\n")
file(WRITE ${OUTPUT}.tmp "${text}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
