// Files for the reader fuzz tests (tests/io/reader_fuzz*_test.cc): the
// shipped files they start from, temporary files the mutated bytes go to,
// and checks of what a reader gives back or says.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

#include "support/test_paths.h"

namespace drape::test {

inline std::string ReadBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Files with these extensions anywhere under resources/ and tests/.
inline std::vector<std::filesystem::path> ShippedFiles(const std::vector<std::string>& extensions) {
  std::vector<std::filesystem::path> files;
  for (const char* dir : {"resources", "tests"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(SourceDir() / dir)) {
      if (!entry.is_regular_file()) continue;
      std::string ext = entry.path().extension().string();
      std::ranges::transform(ext, ext.begin(), [](unsigned char c) { return std::tolower(c); });
      if (std::ranges::find(extensions, ext) != extensions.end()) files.push_back(entry.path());
    }
  }
  std::ranges::sort(files);
  return files;
}

// A file of the system's temporary directory, unique to this process and
// input, removed at the end of its scope.
class TempFile {
 public:
  TempFile(const std::string& extension, const std::string& bytes) {
    static int counter = 0;
    path_ =
        std::filesystem::temp_directory_path() / ("drape-reader-fuzz-" + std::to_string(getpid()) +
                                                  "-" + std::to_string(counter++) + extension);
    std::ofstream(path_, std::ios::binary).write(bytes.data(), std::ssize(bytes));
  }
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

template <class Derived>
bool AllFinite(const Eigen::MatrixBase<Derived>& m) {
  return m.allFinite();
}

// Whether `message` holds `part`, saying what it holds when not.
inline ::testing::AssertionResult Contains(const std::string& message, const std::string& part) {
  if (message.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << message << "' does not contain '" << part << "'";
}

}  // namespace drape::test
