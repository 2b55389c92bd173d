// Helpers for the sweep tests: a temporary folder per test, and results.csv read back into
// rows keyed by column name (through the same CSV splitting the resume logic uses).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "study/sweep/sweep_results.hpp"

namespace tribo::test {

namespace fs = std::filesystem;

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh folder named after the running test, removed afterwards.
class TempDir {
 public:
  explicit TempDir(const std::string& prefix) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / (prefix + info->test_suite_name() + "_" + info->name());
    fs::remove_all(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& sub) const { return path_ / sub; }

 private:
  fs::path path_;
};

using Row = std::map<std::string, std::string>;

inline std::vector<Row> readRows(const fs::path& csv) {
  std::istringstream in(slurp(csv));
  std::string line;
  std::vector<std::string> header;
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    const auto fields = study::splitCsvLine(line);
    if (header.empty()) {
      header = fields;
      continue;
    }
    EXPECT_EQ(fields.size(), header.size()) << line;
    Row r;
    for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i) r[header[i]] = fields[i];
    rows.push_back(r);
  }
  return rows;
}

inline double num(const Row& r, const std::string& column) {
  const auto it = r.find(column);
  if (it == r.end() || it->second.empty()) {
    ADD_FAILURE() << "no value in column " << column;
    return 0;
  }
  return std::stod(it->second);
}

}  // namespace tribo::test
