#include "framework/plugin/registry.h"

#include <unistd.h>
#include <algorithm>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

// Framework headers before GoogleTest's: gtest pulls in <signal.h>, whose si_value macro would
// otherwise rewrite a parameter name in framework/core/quantity.h.
#include "framework/core/error.h"
#include "framework/device/device.h"
#include "framework/model/surface_type.h"
#include "framework/plugin/fingerprint.h"
#include "framework/plugin/test/test_plugin_dirs.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

using test_support::BuildDir;
using test_support::CaseDir;

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

const std::vector<fs::path> kNoFolders;

// The build tree: FITFEEL_BUILD_DIR when set (fitfeel_add_test means to set it), else the folder
// above this test binary, which fitfeel_add_test puts in <build>/tests/. The fallback matters:
// gtest_discover_tests keeps only the first variable of a multi-variable ENVIRONMENT property.

fs::path CaseLibrary(const std::string& name) {
  return fs::canonical(CaseDir(name) / ("libfitfeel_test_" + name + ".so"));
}

// Runs `body`, expects a PluginError and returns its message.
template <class F>
std::string PluginErrorOf(F&& body) {
  try {
    body();
  } catch (const PluginError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a PluginError";
  return {};
}

// Sets or unsets FITFEEL_PLUGIN_PATH for one test and restores it afterwards.
class ScopedPluginPath {
 public:
  explicit ScopedPluginPath(const std::string& value) {
    if (const char* old = std::getenv("FITFEEL_PLUGIN_PATH")) old_ = old;
    setenv("FITFEEL_PLUGIN_PATH", value.c_str(), 1);
  }
  ~ScopedPluginPath() {
    if (old_) {
      setenv("FITFEEL_PLUGIN_PATH", old_->c_str(), 1);
    } else {
      unsetenv("FITFEEL_PLUGIN_PATH");
    }
  }

 private:
  std::optional<std::string> old_;
};

class PluginRegistryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_FALSE(BuildDir().empty())
        << "FITFEEL_BUILD_DIR is not set: run through ctest, or set it to the build tree";
    ASSERT_TRUE(fs::is_directory(CaseDir("good"))) << CaseDir("good") << " was not built";
  }
};

const PluginInfo* FindInfo(const std::vector<PluginInfo>& plugins, const std::string& id) {
  const auto it =
      std::find_if(plugins.begin(), plugins.end(), [&](const PluginInfo& p) { return p.id == id; });
  return it == plugins.end() ? nullptr : &*it;
}

TEST_F(PluginRegistryTest, FindsAndMakesTheGoodPluginsObjects) {
  PluginRegistry registry({CaseDir("good")});
  registry.LoadAll();
  EXPECT_TRUE(registry.refused().empty());
  const std::vector<PluginInfo> plugins = registry.plugins();
  ASSERT_EQ(plugins.size(), 2u);
  const PluginInfo* surface = FindInfo(plugins, "fitfeel.test.inert_surface");
  const PluginInfo* device = FindInfo(plugins, "fitfeel.test.still_device");
  ASSERT_NE(surface, nullptr);
  ASSERT_NE(device, nullptr);
  EXPECT_EQ(surface->kind, kFitfeelSurfacePlugin);
  EXPECT_EQ(device->kind, kFitfeelDevicePlugin);
  EXPECT_EQ(surface->version, "1.0.0");
  EXPECT_EQ(surface->summary, "Test surface type that models nothing");
  EXPECT_EQ(surface->library, CaseLibrary("good"));
  EXPECT_EQ(device->library, CaseLibrary("good"));
  EXPECT_TRUE(registry.Has("fitfeel.test.inert_surface"));
  EXPECT_FALSE(registry.Has("fitfeel.test"));

  const std::shared_ptr<SurfaceType> made_surface =
      registry.MakeSurface("fitfeel.test.inert_surface");
  ASSERT_NE(made_surface, nullptr);
  EXPECT_FALSE(made_surface->renders_forces());
  EXPECT_THAT(made_surface->limitation(), HasSubstr("no resistance law"));
  const std::shared_ptr<Device> made_device = registry.MakeDevice("fitfeel.test.still_device");
  ASSERT_NE(made_device, nullptr);
  EXPECT_EQ(made_device->spec().model, "fitfeel test still device");
  // Each call makes a new object.
  EXPECT_NE(registry.MakeDevice("fitfeel.test.still_device"), made_device);
}

TEST_F(PluginRegistryTest, LoadingALibraryTwiceIsANoOp) {
  PluginRegistry registry(kNoFolders);
  registry.LoadLibrary(CaseLibrary("good"));
  registry.LoadLibrary(CaseDir("good") / "." / "libfitfeel_test_good.so");
  EXPECT_EQ(registry.plugins().size(), 2u);
  // Scanning a folder that holds the same library adds nothing and refuses nothing.
  PluginRegistry scanning({CaseDir("good"), CaseDir("good") / ".." / "good"});
  scanning.LoadAll();
  scanning.LoadAll();
  EXPECT_EQ(scanning.plugins().size(), 2u);
  EXPECT_TRUE(scanning.refused().empty());
}

TEST_F(PluginRegistryTest, MissingIdNamesIdKindFoldersFoundIdsAndRefusals) {
  const fs::path absent = BuildDir() / "test-plugins" / "no-such-folder";
  PluginRegistry registry({CaseDir("good"), absent, CaseDir("wrong_abi")});
  registry.LoadAll();
  const std::string message =
      PluginErrorOf([&] { registry.MakeSurface("fitfeel.surface.conical"); });
  EXPECT_THAT(message, HasSubstr("no surface plugin with id 'fitfeel.surface.conical'"));
  EXPECT_THAT(message, HasSubstr(CaseDir("good").string() + "\n"));
  EXPECT_THAT(message, HasSubstr(absent.string() + " [does not exist]"));
  EXPECT_THAT(message, HasSubstr(CaseDir("wrong_abi").string()));
  EXPECT_THAT(message, HasSubstr("fitfeel.test.inert_surface (surface, " +
                                 CaseLibrary("good").string() + ")"));
  EXPECT_THAT(message, HasSubstr("fitfeel.test.still_device (device, "));
  EXPECT_THAT(message, HasSubstr("refused:\n  " + CaseLibrary("wrong_abi").string() +
                                 ": plugin ABI version mismatch"));
  // Folders are listed in search order.
  EXPECT_LT(message.find(CaseDir("good").string()), message.find(absent.string()));
  EXPECT_LT(message.find(absent.string()), message.find(CaseDir("wrong_abi").string()));
}

TEST_F(PluginRegistryTest, MissingIdBeforeAnyScanSaysSo) {
  PluginRegistry registry({CaseDir("good")});
  const std::string message =
      PluginErrorOf([&] { registry.MakeDevice("fitfeel.device.simulated"); });
  EXPECT_THAT(message, HasSubstr("no device plugin with id 'fitfeel.device.simulated'"));
  EXPECT_THAT(message, HasSubstr("LoadAll() was not called"));
  EXPECT_THAT(message, HasSubstr("found: no plugins"));
}

TEST_F(PluginRegistryTest, AskingForTheWrongKindIsAClearError) {
  PluginRegistry registry({CaseDir("good")});
  registry.LoadAll();
  std::string message = PluginErrorOf([&] { registry.MakeDevice("fitfeel.test.inert_surface"); });
  EXPECT_THAT(message, HasSubstr("'fitfeel.test.inert_surface'"));
  EXPECT_THAT(message, HasSubstr("is a surface plugin, not a device plugin"));
  EXPECT_THAT(message, HasSubstr("device plugins found: fitfeel.test.still_device"));
  message = PluginErrorOf([&] { registry.MakeSurface("fitfeel.test.still_device"); });
  EXPECT_THAT(message, HasSubstr("is a device plugin, not a surface plugin"));
}

TEST_F(PluginRegistryTest, DuplicateIdAcrossLibrariesKeepsTheFirstAndRefusesTheSecond) {
  PluginRegistry registry({CaseDir("duplicate_a"), CaseDir("duplicate_b")});
  registry.LoadAll();
  const std::vector<PluginInfo> plugins = registry.plugins();
  ASSERT_EQ(plugins.size(), 1u);
  EXPECT_EQ(plugins[0].id, "fitfeel.test.duplicate");
  EXPECT_EQ(plugins[0].version, "1.0.0");
  EXPECT_EQ(plugins[0].library, CaseLibrary("duplicate_a"));
  ASSERT_EQ(registry.refused().size(), 1u);
  EXPECT_EQ(registry.refused()[0].library, CaseLibrary("duplicate_b"));
  EXPECT_THAT(registry.refused()[0].reason,
              HasSubstr("duplicate id 'fitfeel.test.duplicate', already provided by " +
                        CaseLibrary("duplicate_a").string()));

  PluginRegistry direct(kNoFolders);
  direct.LoadLibrary(CaseLibrary("duplicate_b"));
  const std::string message =
      PluginErrorOf([&] { direct.LoadLibrary(CaseLibrary("duplicate_a")); });
  EXPECT_THAT(message, HasSubstr(CaseLibrary("duplicate_a").string() + " refused"));
  EXPECT_THAT(message, HasSubstr("already provided by " + CaseLibrary("duplicate_b").string()));
  EXPECT_EQ(direct.plugins().at(0).version, "2.0.0");
}

struct BrokenCase {
  std::string name;
  std::vector<std::string> expected;  // every one must appear in the message
};

void PrintTo(const BrokenCase& c, std::ostream* os) { *os << c.name; }

class BrokenPluginTest : public PluginRegistryTest,
                         public ::testing::WithParamInterface<BrokenCase> {};

TEST_P(BrokenPluginTest, IsRefusedWithItsSpecificReasonAndRegistersNothing) {
  const BrokenCase& c = GetParam();
  PluginRegistry registry(kNoFolders);
  const std::string message = PluginErrorOf([&] { registry.LoadLibrary(CaseLibrary(c.name)); });
  EXPECT_THAT(message, HasSubstr("plugin library " + CaseLibrary(c.name).string() + " refused: "));
  for (const std::string& expected : c.expected) EXPECT_THAT(message, HasSubstr(expected));
  EXPECT_TRUE(registry.plugins().empty());
  EXPECT_TRUE(registry.refused().empty()) << "LoadLibrary throws; only LoadAll records refusals";
}

std::string S(std::size_t n) { return std::to_string(n); }

INSTANTIATE_TEST_SUITE_P(
    EveryBrokenPlugin, BrokenPluginTest,
    ::testing::Values(
        BrokenCase{"wrong_abi",
                   {"plugin ABI version mismatch: expected " + S(FITFEEL_PLUGIN_ABI_VERSION) +
                    ", found " + S(FITFEEL_PLUGIN_ABI_VERSION + 1)}},
        BrokenCase{"wrong_size",
                   {"descriptor size mismatch: expected sizeof(FitfeelPluginDescriptor) = " +
                    S(sizeof(FitfeelPluginDescriptor)) + " bytes, found " +
                    S(sizeof(FitfeelPluginDescriptor) - 8)}},
        BrokenCase{"wrong_align",
                   {"descriptor alignment mismatch: expected alignof(FitfeelPluginDescriptor) = " +
                    S(alignof(FitfeelPluginDescriptor)) + ", found 4"}},
        BrokenCase{
            "wrong_entry_size",
            {"entry size mismatch: expected sizeof(FitfeelPluginEntry) = " +
             S(sizeof(FitfeelPluginEntry)) + " bytes, found " + S(sizeof(FitfeelPluginEntry) + 8)}},
        BrokenCase{"wrong_fingerprint",
                   {"build fingerprint mismatch: expected \"" +
                        std::string(FITFEEL_BUILD_FINGERPRINT) + "\", found \"",
                    "Compatible Clang 15.0.0"}},
        BrokenCase{"no_hook", {"no registration hook", "'fitfeel_plugin_register'", "found none"}},
        BrokenCase{"null_descriptor", {"registration hook returned a null descriptor"}},
        BrokenCase{"null_factory", {"entry #0 ('fitfeel.test.null_factory'): factory is null"}},
        BrokenCase{"malformed_id",
                   {"entry #0: malformed id \"Fitfeel.Test.Bad-Id\"",
                    "dotted lowercase id such as fitfeel.surface.cylindrical"}},
        BrokenCase{"unknown_kind",
                   {"entry #0 ('fitfeel.test.unknown_kind'): unknown kind 7; expected 1 "
                    "(surface) or 2 (device)"}},
        BrokenCase{"duplicate_in_library",
                   {"entry #1 ('fitfeel.test.twice'): duplicate id, already claimed by entry #0"}}),
    [](const ::testing::TestParamInfo<BrokenCase>& p) { return p.param.name; });

const std::vector<std::string> kBrokenCases = {
    "duplicate_in_library", "malformed_id",      "no_hook",   "null_descriptor",
    "null_factory",         "unknown_kind",      "wrong_abi", "wrong_align",
    "wrong_entry_size",     "wrong_fingerprint", "wrong_size"};

TEST_F(PluginRegistryTest, LoadAllSkipsEveryBrokenLibraryAndReportsIt) {
  // Every case folder, in an order that puts broken libraries before and after the good one.
  std::vector<fs::path> path;
  for (const std::string& name : kBrokenCases) path.push_back(CaseDir(name));
  path.insert(path.begin() + 3, CaseDir("good"));
  PluginRegistry registry(path);
  registry.LoadAll();
  registry.LoadAll();  // a second scan neither reloads nor re-reports anything

  std::vector<std::string> ids;
  for (const PluginInfo& p : registry.plugins()) ids.push_back(p.id);
  EXPECT_THAT(ids, ::testing::UnorderedElementsAre("fitfeel.test.inert_surface",
                                                   "fitfeel.test.still_device"));
  ASSERT_EQ(registry.refused().size(), kBrokenCases.size());
  for (std::size_t i = 0; i < kBrokenCases.size(); ++i) {
    EXPECT_EQ(registry.refused()[i].library, CaseLibrary(kBrokenCases[i]));
    EXPECT_FALSE(registry.refused()[i].reason.empty());
    EXPECT_THAT(registry.refused()[i].reason, Not(HasSubstr(" refused: ")))
        << "the reason is the bare reason; the library is its own field";
  }
  // Good plugins stay usable after broken ones were refused around them.
  EXPECT_EQ(registry.MakeDevice("fitfeel.test.still_device")->spec().model,
            "fitfeel test still device");
}

TEST_F(PluginRegistryTest, AFileThatIsNoLibraryIsRefusedWithTheLoaderMessage) {
  const fs::path dir =
      fs::temp_directory_path() / ("fitfeel_registry_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "libnot_a_library.so") << "this is text, not ELF\n";
  std::ofstream(dir / "notes.txt") << "not a plugin name: never opened\n";
  PluginRegistry registry({dir, CaseDir("good")});
  registry.LoadAll();
  ASSERT_EQ(registry.refused().size(), 1u);
  EXPECT_EQ(registry.refused()[0].library.filename(), "libnot_a_library.so");
  EXPECT_THAT(registry.refused()[0].reason, HasSubstr("cannot be loaded: "));
  EXPECT_THAT(registry.refused()[0].reason, Not(HasSubstr("Bad file descriptor")))
      << "only the dynamic loader's own message, not Boost's meaningless errno text";
  EXPECT_THAT(registry.refused()[0].reason, HasSubstr("libnot_a_library.so: file too short"));
  EXPECT_EQ(registry.plugins().size(), 2u);
  const std::string message = PluginErrorOf([&] { registry.LoadLibrary(dir / "libmissing.so"); });
  EXPECT_THAT(message, HasSubstr("libmissing.so refused: no such file"));
  fs::remove_all(dir);
}

TEST_F(PluginRegistryTest, DefaultSearchPathIsEnvironmentThenBuildTreeThenInstallPrefix) {
  const ScopedPluginPath env("/first/folder::/second/folder:");
  const std::vector<fs::path> path = PluginRegistry::DefaultSearchPath();
  ASSERT_EQ(path.size(), 4u);
  EXPECT_EQ(path[0], "/first/folder");
  EXPECT_EQ(path[1], "/second/folder");
  EXPECT_EQ(fs::weakly_canonical(path[2]), fs::weakly_canonical(BuildDir() / "plugins"));
  EXPECT_THAT(path[3].string(), HasSubstr("lib/fitfeel/plugins"));
  EXPECT_THAT(DescribeSearchFolder(path[0]), HasSubstr("(FITFEEL_PLUGIN_PATH) [does not exist]"));
  EXPECT_THAT(DescribeSearchFolder(path[2]), HasSubstr("(build tree)"));
  EXPECT_THAT(DescribeSearchFolder(path[3]), HasSubstr("(install prefix)"));
}

TEST_F(PluginRegistryTest, DefaultSearchPathWithoutEnvironmentHasTheTwoBuiltInFolders) {
  const ScopedPluginPath env("");
  EXPECT_EQ(PluginRegistry::DefaultSearchPath().size(), 2u);
}

TEST_F(PluginRegistryTest, PluginPathOrderDecidesWhichDuplicateWins) {
  for (const bool b_first : {true, false}) {
    const std::string first = b_first ? "duplicate_b" : "duplicate_a";
    const std::string second = b_first ? "duplicate_a" : "duplicate_b";
    const ScopedPluginPath env(CaseDir(first).string() + ":" + CaseDir(second).string());
    PluginRegistry registry;
    registry.LoadAll();
    const std::vector<PluginInfo> plugins = registry.plugins();
    const PluginInfo* duplicate = FindInfo(plugins, "fitfeel.test.duplicate");
    ASSERT_NE(duplicate, nullptr);
    EXPECT_EQ(duplicate->library, CaseLibrary(first));
    EXPECT_EQ(duplicate->version, b_first ? "2.0.0" : "1.0.0");
    const auto refused =
        std::find_if(registry.refused().begin(), registry.refused().end(),
                     [&](const RefusedLibrary& r) { return r.library == CaseLibrary(second); });
    ASSERT_NE(refused, registry.refused().end());
    EXPECT_THAT(refused->reason, HasSubstr("duplicate id 'fitfeel.test.duplicate'"));
  }
}

TEST_F(PluginRegistryTest, ObjectsOutliveTheRegistryThatMadeThem) {
  std::shared_ptr<Device> device;
  std::shared_ptr<SurfaceType> surface;
  {
    PluginRegistry registry({CaseDir("good")});
    registry.LoadAll();
    device = registry.MakeDevice("fitfeel.test.still_device");
    surface = registry.MakeSurface("fitfeel.test.inert_surface");
  }
  // Virtual calls, exceptions thrown from plugin code and destructors all still run.
  device->Start(0.001);
  Wrench wrench;
  wrench.force = {1.0, -2.0, 3.0};
  device->Write(wrench);
  DeviceState state;
  device->Read(0.25, &state);
  EXPECT_EQ(state.time, 0.25);
  EXPECT_EQ(state.delivered.force, wrench.force);
  EXPECT_EQ(device->spec().max_force, 10.0);
  EXPECT_THROW(surface->MakeDiscretizer(), UnsupportedError);
  EXPECT_FALSE(surface->renders_forces());
  device.reset();
  surface.reset();
  // A later registry loads the same library again and works.
  PluginRegistry again({CaseDir("good")});
  again.LoadAll();
  EXPECT_TRUE(again.refused().empty());
  EXPECT_NE(again.MakeDevice("fitfeel.test.still_device"), nullptr);
}

void* NullFactory() { return nullptr; }
void* ThrowingFactory() { throw std::runtime_error("no hardware on this bus"); }
void* UserErrorFactory() { throw UnsupportedError("this device needs a vendor SDK"); }

TEST_F(PluginRegistryTest, InProcessEntriesAreCheckedLikeLibraryEntries) {
  PluginRegistry registry(kNoFolders);
  registry.AddEntry(
      {"fitfeel.device.in_process", kFitfeelDevicePlugin, "0.1.0", "test", &NullFactory});
  ASSERT_TRUE(registry.Has("fitfeel.device.in_process"));
  EXPECT_TRUE(registry.plugins().at(0).library.empty());
  EXPECT_THAT(PluginErrorOf([&] { registry.MakeDevice("fitfeel.device.in_process"); }),
              HasSubstr("(in-process) failed to make its object: its factory returned null"));
  EXPECT_THAT(PluginErrorOf([&] {
                registry.AddEntry({"fitfeel.device.in_process", kFitfeelDevicePlugin, "0.2.0",
                                   "again", &NullFactory});
              }),
              HasSubstr("duplicate id 'fitfeel.device.in_process', already provided by an "
                        "in-process entry"));
  EXPECT_THAT(PluginErrorOf([&] {
                registry.AddEntry({"in process", kFitfeelDevicePlugin, "1", "", &NullFactory});
              }),
              HasSubstr("malformed id \"in process\""));
  EXPECT_THAT(PluginErrorOf([&] {
                registry.AddEntry({"fitfeel.x.y", kFitfeelDevicePlugin, nullptr, "", &NullFactory});
              }),
              HasSubstr("version is null"));
  // A factory's failure reaches the caller as a user error naming the plugin.
  registry.AddEntry({"fitfeel.device.throws", kFitfeelDevicePlugin, "1", "", &ThrowingFactory});
  EXPECT_THAT(PluginErrorOf([&] { registry.MakeDevice("fitfeel.device.throws"); }),
              HasSubstr("plugin 'fitfeel.device.throws' (in-process) failed to make its object: "
                        "no hardware on this bus"));
  registry.AddEntry(
      {"fitfeel.device.unsupported", kFitfeelDevicePlugin, "1", "", &UserErrorFactory});
  EXPECT_THROW(registry.MakeDevice("fitfeel.device.unsupported"), UnsupportedError);
  // A library claiming an in-process id is refused.
  registry.AddEntry({"fitfeel.test.still_device", kFitfeelDevicePlugin, "1", "", &NullFactory});
  EXPECT_THAT(PluginErrorOf([&] { registry.LoadLibrary(CaseLibrary("good")); }),
              HasSubstr("already provided by an in-process entry"));
  EXPECT_FALSE(registry.Has("fitfeel.test.inert_surface")) << "a refused library adds nothing";
}

TEST(PluginIdTest, AcceptsOnlyStableDottedLowercaseIds) {
  for (const char* good : {"fitfeel.surface.cylindrical", "fitfeel.device.simulated", "a.b",
                           "acme.surface.iso_4156_spline", "x1.y2"}) {
    EXPECT_TRUE(IsValidPluginId(good)) << good;
  }
  for (const char* bad : {"", "fitfeel", "Fitfeel.surface", "fitfeel..surface", "fitfeel.surface.",
                          ".fitfeel.surface", "fitfeel.1surface", "fitfeel.surface-x", "fitfeel._x",
                          "fitfeel surface.x", "fitfeel.surface/x"}) {
    EXPECT_FALSE(IsValidPluginId(bad)) << bad;
  }
  EXPECT_TRUE(IsValidPluginId("a." + std::string(126, 'b')));
  EXPECT_FALSE(IsValidPluginId("a." + std::string(127, 'b')));
}

TEST(PluginKindTest, NamesKinds) {
  EXPECT_EQ(PluginKindName(kFitfeelSurfacePlugin), "surface");
  EXPECT_EQ(PluginKindName(kFitfeelDevicePlugin), "device");
  EXPECT_EQ(PluginKindName(9), "unknown kind 9");
}

}  // namespace
}  // namespace fitfeel
