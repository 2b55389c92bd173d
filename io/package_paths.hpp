// Resolves the mesh references of a URDF to files: a plain relative path (against the
// URDF's folder), file:// URIs, and package://NAME/REST through package search paths (the
// --package-path folders, then the folders of ROS_PACKAGE_PATH). A search folder matches a
// package when it is named NAME itself or contains a folder NAME. Not a ROS package crawler:
// package.xml files are not read.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tribo::io {

class PackagePaths {
 public:
  PackagePaths() = default;
  explicit PackagePaths(std::vector<std::string> folders) : folders_(std::move(folders)) {}
  // The given folders followed by those of ROS_PACKAGE_PATH (':'-separated), if set.
  static PackagePaths withEnvironment(std::vector<std::string> folders);

  struct Resolution {
    std::optional<std::string> path;  // the existing file, if found
    std::vector<std::string> tried;   // every candidate looked at, in order
    std::string problem;              // why nothing was found (when !path)
  };
  // `uri` as written in the URDF; `base_folder` is the URDF file's folder.
  Resolution resolve(const std::string& uri, const std::string& base_folder) const;

  const std::vector<std::string>& folders() const { return folders_; }

 private:
  std::vector<std::string> folders_;
};

}  // namespace tribo::io
