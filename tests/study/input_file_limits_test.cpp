// Every reader of a user's file refuses what is not a regular file (a device such as
// /dev/zero, a FIFO, a directory) and a file over its kind's limit, before opening it, with
// its loader's typed error naming the file, what it found (or its size) and the limit. The
// files over a limit are sparse (truncate), so no gigabytes are written; a FIFO is never
// opened, so nothing here can block (a block would show as the CTest timeout).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "contact/mesh_shape.hpp"
#include "io/file_read.hpp"
#include "io/friction_curve.hpp"
#include "io/mesh_loader.hpp"
#include "io/scene_loader.hpp"
#include "io/urdf_reader.hpp"
#include "study/view/view_trajectory.hpp"

namespace tribo {
namespace {

namespace fs = std::filesystem;

class InputFileLimits : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tribo_input_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path fifo(const std::string& name) {
    const fs::path p = dir_ / name;
    EXPECT_EQ(::mkfifo(p.c_str(), 0600), 0);
    return p;
  }
  fs::path folder(const std::string& name) {
    fs::create_directories(dir_ / name);
    return dir_ / name;
  }
  // A sparse file of `bytes` bytes.
  fs::path sized(const std::string& name, std::uintmax_t bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << "";
    fs::resize_file(p, bytes);
    return p;
  }
  fs::path dir_;
};

// What `read` throws for `path`, as text; "" when it does not throw.
std::string errorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

struct Reader {
  std::string kind;                           // the file's kind in messages
  std::string extension;                      // of the test files
  std::uintmax_t limit;                       // bytes
  std::function<void(const fs::path&)> read;  // throws the loader's typed error
};

std::vector<Reader> readers() {
  return {
      {"scene file", ".yaml", io::kMaxSceneBytes,
       [](const fs::path& p) {
         try {
           io::loadScene(p.string());
         } catch (const io::SceneError&) {
           throw;
         } catch (const std::exception& e) {
           ADD_FAILURE() << "not a SceneError: " << e.what();
         }
       }},
      {"URDF file", ".urdf", io::kMaxUrdfBytes,
       [](const fs::path& p) {
         try {
           io::readUrdf(p.string(), {});
         } catch (const io::UrdfError&) {
           throw;
         } catch (const std::exception& e) {
           ADD_FAILURE() << "not a UrdfError: " << e.what();
         }
       }},
      {"mesh file", ".stl", io::kMaxMeshBytes,
       [](const fs::path& p) {
         try {
           io::loadMesh(p.string());
         } catch (const contact::MeshError&) {
           throw;
         } catch (const std::exception& e) {
           ADD_FAILURE() << "not a MeshError: " << e.what();
         }
       }},
      {"friction curve file", ".csv", io::kMaxTableBytes,
       [](const fs::path& p) {
         try {
           io::readFrictionCurve(p.string());
         } catch (const io::SceneError&) {
           throw;
         } catch (const std::exception& e) {
           ADD_FAILURE() << "not a SceneError: " << e.what();
         }
       }},
  };
}

TEST_F(InputFileLimits, DevicesFifosAndDirectoriesAreRefusedBeforeOpening) {
  for (const Reader& r : readers()) {
    SCOPED_TRACE(r.kind);
    const std::string zero = errorOf([&] { r.read("/dev/zero"); });
    EXPECT_TRUE(has(zero, r.kind + " '/dev/zero'") && has(zero, "a character device")) << zero;
    const fs::path pipe = fifo("pipe" + r.extension);
    const std::string f = errorOf([&] { r.read(pipe); });
    EXPECT_TRUE(has(f, pipe.string()) && has(f, "a FIFO")) << f;
    const fs::path d = folder("dir" + r.extension);
    const std::string e = errorOf([&] { r.read(d); });
    EXPECT_TRUE(has(e, d.string()) && has(e, "a directory")) << e;
  }
}

TEST_F(InputFileLimits, FilesJustOverTheirLimitAreRefusedWithSizeAndLimit) {
  for (const Reader& r : readers()) {
    SCOPED_TRACE(r.kind);
    for (const std::uintmax_t over : {r.limit + 1, r.limit + 4096, 4 * r.limit}) {
      const fs::path p = sized("big" + r.extension, over);
      const std::string e = errorOf([&] { r.read(p); });
      const std::string found = std::to_string(over) + " bytes)";
      const std::string limit = std::to_string(r.limit) + " bytes)";
      EXPECT_TRUE(has(e, p.string()) && has(e, found) && has(e, limit)) << e;
    }
    // At the limit the size is no reason to refuse (checked alone: reading the zeros through
    // each parser would only time the parsers).
    const fs::path p = sized("at" + r.extension, r.limit);
    EXPECT_EQ(io::checkReadableFile(p, r.kind, r.limit), r.limit);
  }
}

TEST_F(InputFileLimits, UrdfSniffingDoesNotOpenAFifo) {
  EXPECT_FALSE(io::looksLikeUrdf(fifo("robot.urdf").string()));
  EXPECT_FALSE(io::looksLikeUrdf("/dev/zero"));
}

TEST_F(InputFileLimits, ViewRefusesAnEndlessTrajectoryAndEndlessLines) {
  for (const fs::path& p : {fs::path("/dev/zero"), fifo("trajectory.csv")}) {
    const std::string e = errorOf([&] { study::readViewTrajectory(p, 100, 1000); });
    EXPECT_TRUE(has(e, p.string()) && has(e, "expected a regular file")) << e;
  }
  // A regular file of one line longer than kMaxCsvLineBytes (sparse: NUL bytes).
  const fs::path p = sized("long_line.csv", io::kMaxCsvLineBytes + 10);
  const std::string e = errorOf([&] { study::readViewTrajectory(p, 100, 1000); });
  EXPECT_TRUE(has(e, p.string()) && has(e, "a line longer than")) << e;
  // A good one still reads.
  const fs::path good = dir_ / "good.csv";
  std::ofstream(good) << "t,x\n0,1\n0.1,2\n";
  const study::ViewTrajectory v = study::readViewTrajectory(good, 100, 1000);
  EXPECT_EQ(v.rows, 2u);
}

}  // namespace
}  // namespace tribo
