#include "io/package_paths.hpp"

#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace tribo::io {

namespace fs = std::filesystem;

PackagePaths PackagePaths::withEnvironment(std::vector<std::string> folders) {
  if (const char* env = std::getenv("ROS_PACKAGE_PATH")) {
    std::stringstream s(env);
    std::string item;
    while (std::getline(s, item, ':'))
      if (!item.empty()) folders.push_back(item);
  }
  return PackagePaths(std::move(folders));
}

PackagePaths::Resolution PackagePaths::resolve(const std::string& uri,
                                               const std::string& base_folder) const {
  Resolution r;
  auto consider = [&](const fs::path& candidate) {
    r.tried.push_back(candidate.lexically_normal().string());
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) {
      r.path = candidate.lexically_normal().string();
      return true;
    }
    return false;
  };
  const std::string package_scheme = "package://";
  const std::string file_scheme = "file://";
  if (uri.rfind(package_scheme, 0) == 0) {
    const std::string rest = uri.substr(package_scheme.size());
    const auto slash = rest.find('/');
    if (slash == std::string::npos || slash == 0) {
      r.problem = "malformed package URI (expected package://NAME/PATH)";
      return r;
    }
    const std::string name = rest.substr(0, slash);
    const std::string inside = rest.substr(slash + 1);
    for (const auto& folder : folders_) {
      const fs::path f(folder);
      if (f.filename() == name && consider(f / inside)) return r;
      if (consider(f / name / inside)) return r;
    }
    r.problem = folders_.empty() ? "package '" + name +
                                       "' cannot be found: no package path given "
                                       "(--package-path DIR or ROS_PACKAGE_PATH)"
                                 : "package '" + name + "' has no such file in the package paths";
    return r;
  }
  if (uri.rfind(file_scheme, 0) == 0) {
    if (!consider(fs::path(uri.substr(file_scheme.size())))) r.problem = "no such file";
    return r;
  }
  if (uri.find("://") != std::string::npos) {
    r.problem = "unsupported URI scheme (only relative paths, file:// and package://)";
    return r;
  }
  const fs::path p(uri);
  if (!consider(p.is_absolute() ? p : fs::path(base_folder) / p)) r.problem = "no such file";
  return r;
}

}  // namespace tribo::io
