// Writing a site folder crash-safely (site.hpp: write_site, check_site_folder).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "ek/core/errors.hpp"
#include "ek/site/site.hpp"

namespace ek {
namespace {

namespace fs = std::filesystem;

/// The folder without trailing slashes ("out/" -> "out").
fs::path folder_path(const std::string& dir) {
  require_input(!dir.empty(), "output folder is empty");
  fs::path p(dir);
  while (p.has_filename() == false && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  return p;
}

/// Whether `dir` holds data/site.json of this format (a folder `knots site` wrote).
bool is_site(const fs::path& dir) {
  std::ifstream in(dir / "data" / "site.json");
  if (!in) return false;
  try {
    const auto j = nlohmann::json::parse(in);
    return j.is_object() && j.value("format", std::string()) == kSiteFormat;
  } catch (const std::exception&) {
    return false;
  }
}

void write_file(const fs::path& path, const std::string& content) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.close();
  if (!out) throw InputError("cannot write '" + path.string() + "'");
}

}  // namespace

void check_site_folder(const std::string& dir, bool overwrite) {
  const fs::path p = folder_path(dir);
  std::error_code ec;
  const fs::path parent = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec))
    throw InputError("cannot write '" + dir + "': folder '" + parent.string() + "' does not exist");
  if (::access(parent.c_str(), W_OK) != 0)
    throw InputError("cannot write '" + dir + "': folder '" + parent.string() + "' is not writable");
  if (!fs::exists(p, ec)) return;
  if (!fs::is_directory(p, ec)) throw InputError("cannot write '" + dir + "': it is a file, not a folder");
  if (fs::is_empty(p, ec)) return;
  if (!overwrite)
    throw InputError("'" + dir + "' holds files: choose an empty or new folder, or --overwrite to replace a site");
  if (!is_site(p))
    throw InputError("'" + dir + "' holds files that knots site did not write: not replaced, choose another folder");
}

void write_site(const SiteFiles& files, const std::string& dir, bool overwrite) {
  check_site_folder(dir, overwrite);
  const fs::path p = folder_path(dir);
  const std::string pid = std::to_string(::getpid());
  const fs::path tmp = p.string() + ".tmp." + pid;
  std::error_code ec;
  fs::remove_all(tmp, ec);
  try {
    for (const auto& [rel, content] : files) {
      const fs::path r(rel);
      bool inside = !rel.empty() && r.is_relative();
      for (const auto& part : r) inside = inside && part != ".." && part != ".";
      if (!inside) throw std::logic_error("write_site: a site path must stay inside the folder: '" + rel + "'");
      write_file(tmp / r, content);
    }
    if (!fs::exists(p)) {
      fs::rename(tmp, p);
    } else if (fs::is_empty(p)) {
      fs::remove(p);
      fs::rename(tmp, p);
    } else {  // an earlier site, checked above: swap, then remove the old one
      const fs::path old = p.string() + ".old." + pid;
      fs::rename(p, old);
      fs::rename(tmp, p);
      fs::remove_all(old, ec);
    }
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(tmp, ec);
    throw InputError("cannot write '" + dir + "': " + e.code().message());
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace ek
