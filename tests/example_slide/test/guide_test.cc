// surfaces/README.md quotes this folder: each block preceded by `<!-- file: PATH -->` must be
// that file, byte for byte, and each block preceded by `<!-- excerpt: PATH -->` must appear in it
// word for word, so the guide's code is the code these tests prove. Every file of the folder
// (but this test) must be named in the guide, so a reader learns of each one.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

struct Excerpt {
  std::string path;
  bool whole_file = false;
  std::string body;
};

// Every tagged fenced block of the guide.
std::vector<Excerpt> GuideBlocks(const std::string& guide_text) {
  std::istringstream guide(guide_text);
  std::vector<Excerpt> blocks;
  std::string line;
  while (std::getline(guide, line)) {
    Excerpt block;
    std::string tag;
    for (const char* kind : {"<!-- file: ", "<!-- excerpt: "}) {
      if (line.rfind(kind, 0) == 0) tag = kind;
    }
    if (tag.empty()) continue;
    block.whole_file = tag == "<!-- file: ";
    block.path = line.substr(tag.size(), line.find(" -->") - tag.size());
    std::string fence;
    std::getline(guide, fence);
    fence = fence.substr(0, fence.find_first_not_of('`'));
    EXPECT_GE(fence.size(), 3u) << block.path << ": the tag must sit right above a ``` fence";
    while (std::getline(guide, line) && line != fence) block.body += line + "\n";
    blocks.push_back(block);
  }
  return blocks;
}

TEST(Guide, QuotesTheExampleAsItIs) {
  const std::string guide = Read(kSource / "surfaces/README.md");
  const auto blocks = GuideBlocks(guide);
  EXPECT_GE(blocks.size(), 8u);
  for (const Excerpt& block : blocks) {
    ASSERT_TRUE(fs::exists(kSource / block.path))
        << "the guide quotes " << block.path << ", which does not exist";
    const std::string text = Read(kSource / block.path);
    if (block.whole_file) {
      EXPECT_EQ(block.body, text) << block.path << " differs from its block in the guide";
    } else {
      EXPECT_NE(text.find(block.body), std::string::npos)
          << "the guide's excerpt of " << block.path << " is not in the file:\n" << block.body;
    }
  }
}

TEST(Guide, NamesEveryFileOfTheExample) {
  const std::string guide = Read(kSource / "surfaces/README.md");
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kSource / "tests/example_slide")) {
    if (!entry.is_regular_file()) continue;
    const std::string path = fs::relative(entry.path(), kSource).generic_string();
    if (path == "tests/example_slide/test/guide_test.cc") continue;
    ++files;
    const std::string name =
        fs::relative(entry.path(), kSource / "tests/example_slide").generic_string();
    EXPECT_NE(guide.find(name), std::string::npos)
        << path << " is not named in surfaces/README.md";
  }
  EXPECT_GE(files, 10);
}

}  // namespace
