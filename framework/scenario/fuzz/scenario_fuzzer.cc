// libFuzzer target: the scenario loader with the build tree's real plugins, as `fitfeel validate`
// runs it. Any file either loads into a scene or is refused with a UserError that names the file
// (a ScenarioError: with line, column and key when it points into it). Anything else (a crash,
// another exception, a sanitizer report, a hang past libFuzzer's timeout) is a finding.
// --allow-large is not given: the loader's cost admission keeps a mutated grid from taking minutes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "framework/core/error.h"
#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"
#include "framework/testing/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fitfeel::PluginRegistry* registry = [] {
    auto* r = new fitfeel::PluginRegistry();
    r->LoadAll();
    return r;
  }();
  const std::filesystem::path file =
      fitfeel::test_support::WriteFuzzInput("scenario.yaml", data, size);
  try {
    (void)fitfeel::LoadScene(file, *registry);
  } catch (const fitfeel::ScenarioError& e) {
    if (e.where().file != file.string()) std::abort();
  } catch (const fitfeel::UserError& e) {
    // Any other refusal must still say which file it is about.
    if (std::string(e.what()).find(file.string()) == std::string::npos) std::abort();
  }
  return 0;
}
