#pragma once
// The explorer's pages (src/site/web), embedded at build time by
// src/site/embed_assets.cmake: (path relative to the site, contents).
#include <string_view>
#include <utility>
#include <vector>

namespace ek {

const std::vector<std::pair<const char*, std::string_view>>& site_assets();

}  // namespace ek
