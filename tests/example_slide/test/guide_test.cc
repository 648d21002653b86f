// surfaces/README.md walks through this folder file by file: each block preceded by
// `<!-- file: tests/example_slide/... -->` must be that file, byte for byte, and every file of
// the folder (but this test) must have its block, so copying the guide's blocks rebuilds the
// plugin these tests prove.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

const fs::path kSource = FITFEEL_TEST_SOURCE_DIR;

std::string Read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Path -> content of every tagged fenced block of the guide.
std::map<std::string, std::string> GuideBlocks() {
  std::istringstream guide(Read(kSource / "surfaces/README.md"));
  std::map<std::string, std::string> blocks;
  const std::string tag = "<!-- file: ";
  std::string line;
  while (std::getline(guide, line)) {
    if (line.rfind(tag, 0) != 0) continue;
    const std::string path = line.substr(tag.size(), line.find(" -->") - tag.size());
    std::string fence;
    std::getline(guide, fence);
    fence = fence.substr(0, fence.find_first_not_of('`'));
    EXPECT_GE(fence.size(), 3u) << path << ": the tag must sit right above a ``` fence";
    std::string body;
    while (std::getline(guide, line) && line != fence) body += line + "\n";
    EXPECT_TRUE(blocks.emplace(path, body).second) << path << " shown twice";
  }
  return blocks;
}

TEST(Guide, ShowsEveryFileOfTheExampleAsItIs) {
  const auto blocks = GuideBlocks();
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kSource / "tests/example_slide")) {
    if (!entry.is_regular_file()) continue;
    const std::string path = fs::relative(entry.path(), kSource).generic_string();
    if (path == "tests/example_slide/test/guide_test.cc") continue;
    ++files;
    const auto it = blocks.find(path);
    if (it == blocks.end()) {
      ADD_FAILURE() << path << " is not shown in surfaces/README.md";
      continue;
    }
    EXPECT_EQ(it->second, Read(entry.path())) << path << " differs from its block in the guide";
  }
  EXPECT_GE(files, 10);
  for (const auto& [path, body] : blocks) {
    EXPECT_TRUE(fs::exists(kSource / path))
        << "the guide shows " << path << ", which does not exist";
  }
}

}  // namespace
