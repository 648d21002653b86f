// `fitfeel plugins`: what the registry found, where it looked, and what it refused and why.

#include <algorithm>
#include <cstddef>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/model/surface_type.h"
#include "framework/plugin/registry.h"

namespace fitfeel::cli {
namespace {

struct Row {
  PluginInfo info;
  // For surfaces: whether the type renders forces, and if not, why (its limitation()).
  std::optional<bool> renders_forces;
  std::string note;
};

// A surface's limitation is only known from an instance, so each surface is made once; a factory
// that fails is reported on its row rather than aborting the listing.
std::vector<Row> CollectRows(const PluginRegistry& registry) {
  std::vector<Row> rows;
  for (const PluginInfo& info : registry.plugins()) {
    Row row{info, std::nullopt, {}};
    if (info.kind == kFitfeelSurfacePlugin) {
      try {
        const std::shared_ptr<SurfaceType> surface = registry.MakeSurface(info.id);
        row.renders_forces = surface->renders_forces();
        if (!surface->renders_forces()) row.note = surface->limitation();
      } catch (const UserError& e) {
        row.note = std::string("cannot be instantiated: ") + e.what();
      }
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string PadRight(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

void PrintText(const PluginRegistry& registry, const std::vector<Row>& rows) {
  std::cout << "plugins (" << rows.size() << "):\n";
  if (rows.empty()) {
    std::cout << "  none\n";
  } else {
    std::size_t id_width = 2, kind_width = 4, version_width = 7;
    for (const Row& row : rows) {
      id_width = std::max(id_width, row.info.id.size());
      kind_width = std::max(kind_width, PluginKindName(row.info.kind).size());
      version_width = std::max(version_width, row.info.version.size());
    }
    const std::string indent(2 + id_width + 2, ' ');
    std::cout << "  " << PadRight("ID", id_width) << "  " << PadRight("KIND", kind_width) << "  "
              << PadRight("VERSION", version_width) << "  SUMMARY\n";
    for (const Row& row : rows) {
      std::cout << "  " << PadRight(row.info.id, id_width) << "  "
                << PadRight(PluginKindName(row.info.kind), kind_width) << "  "
                << PadRight(row.info.version, version_width) << "  " << row.info.summary << "\n";
      std::cout << indent << "library: "
                << (row.info.library.empty() ? std::string("(in-process)")
                                             : row.info.library.string())
                << "\n";
      if (row.renders_forces.has_value() && !*row.renders_forces) {
        std::cout << indent << "renders no forces: " << row.note << "\n";
      } else if (!row.note.empty()) {
        std::cout << indent << row.note << "\n";
      }
    }
  }
  std::cout << "searched, in order:\n";
  for (const auto& folder : registry.search_path()) {
    std::cout << "  " << DescribeSearchFolder(folder) << "\n";
  }
  std::cout << "refused (" << registry.refused().size() << "):";
  if (registry.refused().empty()) std::cout << " none";
  std::cout << "\n";
  for (const RefusedLibrary& refused : registry.refused()) {
    std::cout << "  " << refused.library.string() << "\n    " << refused.reason << "\n";
  }
}

void PrintJson(const PluginRegistry& registry, const std::vector<Row>& rows) {
  nlohmann::json out;
  out["plugins"] = nlohmann::json::array();
  for (const Row& row : rows) {
    nlohmann::json item = {{"id", row.info.id},
                           {"kind", PluginKindName(row.info.kind)},
                           {"version", row.info.version},
                           {"summary", row.info.summary},
                           {"library", row.info.library.string()}};
    if (row.renders_forces.has_value()) item["renders_forces"] = *row.renders_forces;
    if (!row.note.empty()) item["limitation"] = row.note;
    out["plugins"].push_back(std::move(item));
  }
  out["search_path"] = nlohmann::json::array();
  for (const auto& folder : registry.search_path()) {
    std::error_code ec;
    out["search_path"].push_back(
        {{"path", folder.string()}, {"exists", std::filesystem::is_directory(folder, ec)}});
  }
  out["refused"] = nlohmann::json::array();
  for (const RefusedLibrary& refused : registry.refused()) {
    out["refused"].push_back({{"library", refused.library.string()}, {"reason", refused.reason}});
  }
  std::cout << out.dump(2) << "\n";
}

}  // namespace

void AddPluginsCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "plugins",
      "List every plugin found (id, kind, version, library, summary), the folders searched "
      "(FITFEEL_PLUGIN_PATH, the build tree, the install prefix) and the libraries refused");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "Print the listing as JSON");
  cmd->callback([json] {
    PluginRegistry registry;
    registry.LoadAll();
    const std::vector<Row> rows = CollectRows(registry);
    if (*json) {
      PrintJson(registry, rows);
    } else {
      PrintText(registry, rows);
    }
  });
}

}  // namespace fitfeel::cli
