#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/export.h"

namespace fitfeel::plot {

// Image formats the charts are written in.
enum class ImageFormat { kPng, kSvg };

FITFEEL_API std::string_view Extension(ImageFormat format);  // ".png" / ".svg"

struct OutputFile {
  std::filesystem::path path;
  ImageFormat format = ImageFormat::kPng;
};

// Interprets the `-o FILE` of a plot command: FILE.png or FILE.svg writes that format, FILE
// without an extension writes FILE.png and FILE.svg. Throws UserError for any other extension,
// an empty name, or a folder that does not exist.
FITFEEL_API std::vector<OutputFile> ResolveOutputs(const std::filesystem::path& file);

// A gnuplot string literal holding `text` verbatim. Single quotes, because gnuplot runs
// `backquoted` shell commands inside double-quoted strings; control characters become spaces so
// that text cannot end the command line.
FITFEEL_API std::string QuoteForGnuplot(std::string_view text);

// A private folder (mkdtemp, mode 0700) for scripts, data and images; removed on destruction.
class FITFEEL_API TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The gnuplot executable, driven as a subprocess with a script file (no shell involved).
class FITFEEL_API Gnuplot {
 public:
  // $FITFEEL_GNUPLOT when set, else `gnuplot` on $PATH; nullopt when there is none.
  static std::optional<std::filesystem::path> Locate();
  // Like Locate(), but throws UnsupportedError naming the Debian package when gnuplot is absent.
  static Gnuplot Find();

  explicit Gnuplot(std::filesystem::path executable) : executable_(std::move(executable)) {}
  const std::filesystem::path& executable() const { return executable_; }

  // Runs `gnuplot -d <script>` (default settings, no ~/.gnuplot) with `work_dir` as its working
  // folder, stdin from /dev/null. Throws std::runtime_error with gnuplot's messages when it exits
  // non-zero, is killed, or writes anything but Fontconfig notes to stderr (its warnings mean a
  // chart lost data).
  void Run(const std::filesystem::path& script, const std::filesystem::path& work_dir) const;

 private:
  std::filesystem::path executable_;
};

// Copies `source` to `target` through a temporary name in the target's folder and a rename, so a
// reader never sees a half-written file. Throws UserError when the target cannot be written.
FITFEEL_API void InstallAtomically(const std::filesystem::path& source,
                                   const std::filesystem::path& target);

}  // namespace fitfeel::plot
