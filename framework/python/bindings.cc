// The Python module fitfeel._fitfeel (docs/embedding.md, "Python"): scenes, skin model shapes as
// NumPy arrays, runs as arrays and dicts, studies and single study pairs (for a Dask cluster).
// Every call that runs the model releases the GIL. User errors arrive as fitfeel.UserError (and
// its subclass fitfeel.ScenarioError) with the CLI's located message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/plot/study_chart.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/run.h"
#include "framework/runtime/scene_stages.h"
#include "framework/runtime/tick_observer.h"
#include "framework/runtime/trace_columns.h"
#include "framework/scenario/scene.h"
#include "framework/scenario/scene_summary.h"
#include "framework/study/study.h"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace fitfeel::python {
namespace {

// One registry per process, loaded on first use: plugins load once, whatever the calls.
const PluginRegistry& Registry() {
  static std::once_flag once;
  static std::unique_ptr<PluginRegistry> registry;
  std::call_once(once, [] {
    registry = std::make_unique<PluginRegistry>();
    registry->LoadAll();
  });
  return *registry;
}

// JSON -> Python objects (dicts, lists, floats, ints, str, None).
py::object ToPython(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (const auto& [k, v] : j.items()) d[py::str(k)] = ToPython(v);
      return d;
    }
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto& v : j) l.append(ToPython(v));
      return l;
    }
    case nlohmann::json::value_t::string:
      return py::str(j.get<std::string>());
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.get<double>());
    default:
      return py::none();
  }
}

template <typename T>
py::array_t<T> Array(std::vector<T> values) {
  auto* heap = new std::vector<T>(std::move(values));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(static_cast<py::ssize_t>(heap->size()), heap->data(), owner);
}

py::array_t<double> Matrix(const Eigen::VectorXd& v, int rows, int columns) {
  py::array_t<double> a({rows, columns});
  auto m = a.mutable_unchecked<2>();
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) m(i, j) = v(i * columns + j);
  }
  return a;
}

py::dict ShapeDict(const PartSpec& part, const SkinModelShape& s) {
  const SurfaceGrid& g = s.grid;
  py::dict d;
  d["role"] = part.role == Role::kInner ? "inner" : "outer";
  d["rows"] = g.rows;
  d["columns"] = g.columns;
  d["row_position"] = Array(
      std::vector<double>(g.row_position.data(), g.row_position.data() + g.row_position.size()));
  d["column_angle"] = Array(
      std::vector<double>(g.column_angle.data(), g.column_angle.data() + g.column_angle.size()));
  d["variation"] = Matrix(s.variation, g.rows, g.columns);
  d["dimension_part"] = Matrix(s.dimension_part, g.rows, g.columns);
  d["form_part"] = Matrix(s.form_part, g.rows, g.columns);
  d["surface_part"] = Matrix(s.surface_part, g.rows, g.columns);
  d["rejections"] = s.rejections;
  return d;
}

// Collects the run's records on the writer thread (never in the tick) as trace.csv's columns:
// TraceValues is the CSV writer's own definition of them.
class TraceCollector final : public TickObserver {
 public:
  TraceCollector(std::vector<std::string> features, bool screw)
      : features_(std::move(features)),
        screw_(screw),
        count_(TraceColumnCount(static_cast<int>(features_.size()), screw)),
        columns_(static_cast<std::size_t>(count_)),
        row_(static_cast<std::size_t>(count_)) {}
  void OnTick(const TickRecord&) noexcept override {}
  void OnRecord(const TickRecord& r, std::uint64_t) override {
    TraceValues(r, static_cast<int>(features_.size()), screw_, row_.data());
    for (std::size_t k = 0; k < row_.size(); ++k) columns_[k].push_back(row_[k]);
  }
  // Column name -> array, in trace.csv's order; the stage and the 0/1 flags as integers.
  py::dict Take() {
    py::dict d;
    const std::vector<TraceColumn> columns = TraceColumns(features_, screw_);
    for (std::size_t k = 0; k < columns.size(); ++k) {
      std::vector<double>& v = columns_[k];
      if (columns[k].kind == TraceColumnKind::kNumber) {
        d[py::str(columns[k].name)] = Array(std::move(v));
      } else {
        d[py::str(columns[k].name)] = Array(std::vector<int>(v.begin(), v.end()));
      }
    }
    return d;
  }

 private:
  std::vector<std::string> features_;
  bool screw_;
  int count_;
  std::vector<std::vector<double>> columns_;
  std::vector<double> row_;
};

py::dict PairDict(const study::PairResult& p) {
  py::dict d;
  d["pair"] = p.pair;
  d["seed"] = p.seed;
  d["shaft_size_um"] = p.shaft_size_um;
  d["hole_size_um"] = p.hole_size_um;
  d["min_clearance_um"] =
      p.min_clearance_um ? py::object(py::float_(*p.min_clearance_um)) : py::object(py::none());
  d["interfering"] = p.interfering;
  d["axial_mean_N"] = p.axial_mean_N;
  d["axial_max_N"] = p.axial_max_N;
  d["radial_max_N"] = p.radial_max_N;
  d["constrained_ticks"] = p.constrained_ticks;
  d["elastic_utilisation_max"] = p.elastic_utilisation_max
                                     ? py::object(py::float_(*p.elastic_utilisation_max))
                                     : py::object(py::none());
  d["plastic"] = p.plastic;
  d["rejections"] = p.rejections;
  d["prepare_s"] = p.prepare_s;
  d["wall_s"] = p.wall_s;
  return d;
}

study::PairResult PairFromDict(const py::dict& d) {
  study::PairResult p;
  p.pair = d["pair"].cast<int>();
  p.seed = d["seed"].cast<std::uint64_t>();
  p.shaft_size_um = d["shaft_size_um"].cast<double>();
  p.hole_size_um = d["hole_size_um"].cast<double>();
  if (!d["min_clearance_um"].is_none()) p.min_clearance_um = d["min_clearance_um"].cast<double>();
  p.interfering = d["interfering"].cast<bool>();
  p.axial_mean_N = d["axial_mean_N"].cast<double>();
  p.axial_max_N = d["axial_max_N"].cast<double>();
  p.radial_max_N = d["radial_max_N"].cast<double>();
  p.constrained_ticks = d["constrained_ticks"].cast<int>();
  if (!d["elastic_utilisation_max"].is_none()) {
    p.elastic_utilisation_max = d["elastic_utilisation_max"].cast<double>();
  }
  p.plastic = d["plastic"].cast<bool>();
  p.rejections = d["rejections"].cast<int>();
  p.prepare_s = d["prepare_s"].cast<double>();
  p.wall_s = d["wall_s"].cast<double>();
  return p;
}

}  // namespace
}  // namespace fitfeel::python

PYBIND11_MODULE(_fitfeel, m) {
  using namespace fitfeel;
  using namespace fitfeel::python;
  m.doc() = "fitfeel: feel a fit computed from ISO GPS tolerances (docs/embedding.md)";

  static py::exception<UserError> user_error(m, "UserError", PyExc_ValueError);
  static py::exception<ScenarioError> scenario_error(m, "ScenarioError", user_error.ptr());
  // Tried most specific first: a ScenarioError is a UserError too.
  py::register_exception_translator([](std::exception_ptr e) {
    try {
      if (e) std::rethrow_exception(e);
    } catch (const ScenarioError& x) {
      scenario_error(x.what());
    } catch (const UserError& x) {
      user_error(x.what());
    }
  });

  m.attr("STAGES") = py::make_tuple(std::string(ToString(StageId::kPositioning)),
                                    std::string(ToString(StageId::kConstrained)));

  m.def(
      "validate",
      [](const std::string& file) {
        const Scene scene = LoadScene(file, Registry());
        return DescribeScene(scene);
      },
      py::arg("file"),
      "Loads and checks a scenario; returns what `fitfeel validate` prints. Raises ScenarioError.");

  m.def(
      "skin_model_shapes",
      [](const std::string& file, std::optional<std::uint64_t> seed) {
        LoadOptions load;
        load.allow_non_rendering = true;
        const Scene scene = LoadScene(file, Registry(), load);
        SkinModelShapes shapes;
        {
          py::gil_scoped_release release;
          Rng rng(seed.value_or(scene.run.seed));
          shapes = GenerateSkinModelShapes(scene, rng);
        }
        py::dict d;
        d[py::str(scene.inner.name)] = ShapeDict(scene.inner, shapes.inner);
        d[py::str(scene.outer.name)] = ShapeDict(scene.outer, shapes.outer);
        return d;
      },
      py::arg("file"), py::arg("seed") = py::none(),
      "Both parts' skin model shapes as `fitfeel run` draws them: per part a dict with "
      "`variation` (rows x columns, m) and its parts, `row_position` (m), `column_angle` (rad).");

  m.def(
      "run",
      [](const std::string& file, std::optional<std::uint64_t> seed,
         std::optional<std::string> out) {
        Scene scene = LoadScene(file, Registry());
        std::vector<std::string> features;
        for (const MatingFeature& feature : scene.features) features.push_back(feature.name);
        TraceCollector trace(std::move(features), IsScrewScene(scene));
        RunResult result;
        {
          py::gil_scoped_release release;
          RunOptions options;
          options.seed = seed;
          options.clock = ClockMode::kVirtual;
          options.observer = &trace;
          if (out) options.out_dir = *out;
          result = RunScene(std::move(scene), options);
        }
        py::dict t = trace.Take();
        return py::make_tuple(t, ToPython(result.summary));
      },
      py::arg("file"), py::arg("seed") = py::none(), py::arg("out") = py::none(),
      "Runs a scenario in virtual time; returns (trace, summary): the trace as a dict of NumPy "
      "arrays, one per column of `trace.csv` with its name and unit, in its order (`stage` as "
      "an index into STAGES, 0/1 flags as integers), the summary as `summary.json`'s dict. With "
      "`out`, also writes the run's files there.");

  m.def(
      "study_pair",
      [](const std::string& file, std::uint64_t seed, int index) {
        study::PairResult p;
        {
          py::gil_scoped_release release;
          p = study::RunStudyPair(file, Registry(), seed, index);
        }
        return PairDict(p);
      },
      py::arg("file"), py::arg("seed"), py::arg("index"),
      "Pair `index` of the study seeded `seed`: the same row `fitfeel study` computes for it.");

  m.def(
      "study_on_threads",
      [](const std::string& file, int pairs, std::uint64_t seed, int threads,
         std::optional<std::string> out) {
        study::StudyResult r;
        {
          py::gil_scoped_release release;
          study::StudySettings s;
          s.pairs = pairs;
          s.seed = seed;
          s.threads = threads;
          r = study::RunStudy(file, Registry(), s);
          if (out) {
            study::WriteStudy(*out, r);
            plot::WriteStudyChart(*out);
          }
        }
        py::list rows;
        for (const auto& p : r.pairs) rows.append(PairDict(p));
        return py::make_tuple(rows, ToPython(nlohmann::json::parse(study::StudyJson(r))));
      },
      py::arg("file"), py::arg("pairs") = 100, py::arg("seed") = 1, py::arg("threads") = 1,
      py::arg("out") = py::none(),
      "A fit study on this machine's threads; returns (pairs, study): the rows of pairs.csv as "
      "dicts and study.json as a dict. With `out`, writes pairs.csv, study.json and study.png "
      "there, as `fitfeel study` does.");

  m.def(
      "write_study",
      [](const std::string& dir, const std::string& file, std::uint64_t seed, int requested,
         const py::list& pairs, int workers, double wall_s) {
        study::StudyResult r;
        r.scenario = LoadScene(file, Registry()).name;
        r.scenario_file = file;
        r.seed = seed;
        r.requested_pairs = requested;
        r.threads = workers;
        r.wall_s = wall_s;
        for (const auto& p : pairs) r.pairs.push_back(PairFromDict(p.cast<py::dict>()));
        for (std::size_t i = 0; i < r.pairs.size(); ++i) {
          if (r.pairs[i].pair != static_cast<int>(i)) {
            throw UserError("write_study: pairs must be 0 .. n-1 in order; position " +
                            std::to_string(i) + " holds pair " + std::to_string(r.pairs[i].pair));
          }
        }
        r.interrupted = static_cast<int>(r.pairs.size()) < requested;
        py::gil_scoped_release release;
        study::WriteStudy(dir, r);
        plot::WriteStudyChart(dir);
      },
      py::arg("dir"), py::arg("file"), py::arg("seed"), py::arg("requested"), py::arg("pairs"),
      py::arg("workers"), py::arg("wall_s"),
      "Writes pairs.csv and study.json of pairs computed elsewhere (study_pair), both or neither, "
      "then study.png from them, as `fitfeel study` does.");
}
