// The compiled part of the Python module: scenes from a file or a dict (with overrides), a scene
// run returning its summary and its tables as numpy arrays, the stability sweep, and hpcontact's
// InputError as a Python exception with the same message. hpcontact/__init__.py wraps these.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <toml++/toml.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>

#include "core/error.hpp"
#include "core/memory_limit.hpp"
#include "core/petsc_session.hpp"
#include "driver/scene_run.hpp"
#include "driver/summary_json.hpp"
#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"
#include "library_thread.hpp"
#include "run_result_bindings.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_reader.hpp"
#include "studies/pairing_advice.hpp"
#include "studies/stability_sweep.hpp"
#include "studies/sweep_folder.hpp"
#include "studies/sweep_verdicts.hpp"
#include "vtu_grid_arrays.hpp"

namespace py = pybind11;
using namespace hpcontact;

namespace {

// PETSc/SLEPc start on the first path that needs them (as in the command-line tool) and stop when
// the interpreter exits.
std::unique_ptr<PetscSession>& session() {
  static std::unique_ptr<PetscSession> instance;
  return instance;
}

// What a Python scalar is to a scene: numpy's scalars count as Python's (numpy.int64 is an integer,
// numpy.float32 a number, numpy.bool_ a boolean).
enum class ScalarKind { boolean, integer, number, text, other };

ScalarKind kind_of(const py::handle& value) {
  // (Never destroyed: a static py::object would be released after the interpreter ends.)
  static const py::object& real = *new py::object(py::module_::import("numbers").attr("Real"));
  const py::handle type = py::type::handle_of(value);
  const std::string module = py::str(type.attr("__module__")), name = py::str(type.attr("__name__"));
  // numpy.bool_ is named "bool" from NumPy 2 on.
  if (py::isinstance<py::bool_>(value) || (module == "numpy" && (name == "bool_" || name == "bool")))
    return ScalarKind::boolean;
  if (py::isinstance<py::str>(value)) return ScalarKind::text;
  if (py::hasattr(value, "__len__")) return ScalarKind::other;  // (an array of one integer has __index__)
  if (py::hasattr(value, "__index__")) return ScalarKind::integer;
  if (PyObject_IsInstance(value.ptr(), real.ptr()) == 1) return ScalarKind::number;
  return ScalarKind::other;
}

// A Python integer of any size as a 64-bit one. @throws InputError naming the key if it does not fit.
long long integer_of(const std::string& key, const py::handle& value) {
  PyObject* index = PyNumber_Index(value.ptr());
  if (!index) throw py::error_already_set();
  const py::int_ integer = py::reinterpret_steal<py::int_>(index);
  int overflow = 0;
  const long long result = PyLong_AsLongLongAndOverflow(integer.ptr(), &overflow);
  if (overflow != 0)
    throw InputError("override '" + key + "' = " + py::str(py::handle(integer)).cast<std::string>() +
                     ": an integer between -2^63 and 2^63 - 1");
  return result;
}

// A list, a tuple or a numpy array of one dimension or more (numpy's scalars have
// __array_interface__ too, with no dimension).
bool is_sequence(const py::handle& value) {
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) return true;
  return py::hasattr(value, "__array_interface__") && py::hasattr(value, "ndim") &&
         py::int_(value.attr("ndim")).cast<int>() >= 1;
}

// Items that are all sequences of numbers ([[x, y], ...], a 2-D array) as lists of numbers.
std::optional<std::vector<std::vector<double>>> number_lists_of(const py::list& items) {
  std::vector<std::vector<double>> lists;
  for (const auto& item : items) {
    if (!is_sequence(item)) return std::nullopt;
    std::vector<double>& numbers = lists.emplace_back();
    for (const auto& element : py::list(item.cast<py::object>())) {
      const ScalarKind kind = kind_of(element);
      if (kind != ScalarKind::integer && kind != ScalarKind::number) return std::nullopt;
      numbers.push_back(py::float_(element.cast<py::object>()).cast<double>());
    }
  }
  if (lists.empty()) return std::nullopt;
  return lists;
}

// A Python value as a scene override (numbers, booleans, text, lists or arrays of one kind, lists
// of number lists).
scene::SceneOverride::Value override_value(const std::string& key, const py::handle& value) {
  // A numpy array of no dimension holds one scalar.
  if (py::hasattr(value, "ndim") && py::hasattr(value, "item") && py::int_(value.attr("ndim")).cast<int>() == 0)
    return override_value(key, value.attr("item")());
  switch (kind_of(value)) {
    case ScalarKind::boolean:
      return py::bool_(value.cast<py::object>()).cast<bool>();
    case ScalarKind::integer:
      return integer_of(key, value);
    case ScalarKind::number:
      return py::float_(value.cast<py::object>()).cast<double>();
    case ScalarKind::text:
      return value.cast<std::string>();
    case ScalarKind::other:
      break;
  }
  if (is_sequence(value)) {
    const auto items = py::list(value.cast<py::object>());
    if (auto lists = number_lists_of(items)) return *lists;
    bool all_int = true, all_number = true;
    for (const auto& item : items) {
      const ScalarKind kind = kind_of(item);
      all_int = all_int && kind == ScalarKind::integer;
      all_number = all_number && (kind == ScalarKind::integer || kind == ScalarKind::number);
    }
    if (all_int) {
      std::vector<long long> integers;
      for (const auto& item : items) integers.push_back(integer_of(key, item));
      return integers;
    }
    if (all_number) {
      std::vector<double> numbers;
      for (const auto& item : items) numbers.push_back(py::float_(item.cast<py::object>()).cast<double>());
      return numbers;
    }
    // Text, or text and numbers mixed (ratio = ["1/2", 1]): read as text, as in a scene file.
    std::vector<std::string> texts;
    for (const auto& item : items) texts.push_back(py::str(item).cast<std::string>());
    return texts;
  }
  throw InputError("override '" + key +
                   "': a number, a boolean, a string, a list of them or a list of number lists, not " +
                   py::str(py::type::handle_of(value)).cast<std::string>());
}

std::vector<scene::SceneOverride> overrides_of(const py::dict& overrides) {
  std::vector<scene::SceneOverride> out;
  for (const auto& [key, value] : overrides) {
    const std::string name = py::str(key).cast<std::string>();
    out.push_back({name, override_value(name, value), "Python override " + name});
  }
  return out;
}

// A dict as TOML: tables, arrays, strings, integers, floats, booleans, put into `table` under
// `key` (or appended to `array`).
void put(const py::handle& value, const std::string& where, toml::table* table, const std::string& key,
         toml::array* array);

template <typename T>
void put_value(T&& node, toml::table* table, const std::string& key, toml::array* array) {
  if (table)
    table->insert_or_assign(key, std::forward<T>(node));
  else
    array->push_back(std::forward<T>(node));
}

toml::table toml_table(const py::dict& dict, const std::string& where) {
  toml::table out;
  for (const auto& [key, item] : dict) {
    const std::string name = py::str(key).cast<std::string>();
    put(item, where.empty() ? name : where + "." + name, &out, name, nullptr);
  }
  return out;
}

void put(const py::handle& value, const std::string& where, toml::table* table, const std::string& key,
         toml::array* array) {
  if (py::isinstance<py::bool_>(value)) return put_value(value.cast<bool>(), table, key, array);
  if (py::isinstance<py::int_>(value)) return put_value(value.cast<int64_t>(), table, key, array);
  if (py::isinstance<py::float_>(value)) return put_value(value.cast<double>(), table, key, array);
  if (py::isinstance<py::str>(value)) return put_value(value.cast<std::string>(), table, key, array);
  if (py::isinstance<py::dict>(value)) return put_value(toml_table(value.cast<py::dict>(), where), table, key, array);
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    toml::array items;
    for (const auto& item : value.cast<py::sequence>()) put(item, where + "[]", nullptr, "", &items);
    return put_value(std::move(items), table, key, array);
  }
  throw InputError("scene dict: key '" + where + "' holds a " +
                   py::str(py::type::handle_of(value)).cast<std::string>() +
                   "; allowed are dicts, lists, strings, integers, floats and booleans");
}

// A table's columns: numbers as float64 (or int64) arrays, text as lists of str.
py::dict columns_of(const io::CsvTable& table) {
  py::dict out;
  const auto& rows = table.rows();
  for (std::size_t c = 0; c < table.columns().size(); ++c) {
    bool integers = true, numbers = true;
    for (const auto& row : rows) {
      integers = integers && std::holds_alternative<long long>(row[c]);
      numbers = numbers && !std::holds_alternative<std::string>(row[c]);
    }
    const auto n = static_cast<py::ssize_t>(rows.size());
    if (integers) {
      py::array_t<long long> column(n);
      auto view = column.mutable_unchecked<1>();
      for (py::ssize_t r = 0; r < n; ++r) view(r) = std::get<long long>(rows[r][c]);
      out[py::str(table.columns()[c])] = column;
    } else if (numbers) {
      py::array_t<double> column(n);
      auto view = column.mutable_unchecked<1>();
      for (py::ssize_t r = 0; r < n; ++r)
        view(r) = std::holds_alternative<double>(rows[r][c]) ? std::get<double>(rows[r][c])
                                                             : static_cast<double>(std::get<long long>(rows[r][c]));
      out[py::str(table.columns()[c])] = column;
    } else {
      py::list column;
      for (const auto& row : rows)
        column.append(std::visit(
            [](const auto& v) -> py::object {
              using T = std::decay_t<decltype(v)>;
              if constexpr (std::is_same_v<T, std::string>)
                return py::str(v);
              else
                return py::cast(v);
            },
            row[c]));
      out[py::str(table.columns()[c])] = column;
    }
  }
  return out;
}

// summary.json's text as a dict (the one JSON writer: driver::summary_json).
py::object json_to_python(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

// Scenes: the checked Scene, from a file or a dict of tables, with overrides.
void bind_scenes(py::module_& m) {
  py::class_<scene::Scene>(m, "Scene", "A checked scene (read_scene, scene_from_dict)")
      .def_property_readonly("file", [](const scene::Scene& s) { return s.file; })
      .def_property_readonly("effects",
                             [](const scene::Scene& s) {
                               std::vector<std::string> names;
                               for (auto effect : s.effects) names.push_back(scene::to_string(effect));
                               return names;
                             })
      .def("__repr__", [](const scene::Scene& s) { return "<hpcontact.Scene " + s.file + ">"; });

  m.def(
      "read_scene",
      [](const std::string& path, const py::dict& overrides) {
        return scene::read_scene(path, overrides_of(overrides));
      },
      py::arg("path"), py::arg("overrides") = py::dict(), "The scene of a TOML file, with dotted-key overrides");
  m.def(
      "scene_from_dict",
      [](const py::dict& tables, const std::string& path, const py::dict& overrides) {
        std::ostringstream text;
        text << toml_table(tables, "");
        return scene::parse_scene(text.str(), path, overrides_of(overrides));
      },
      py::arg("tables"), py::arg("path"), py::arg("overrides") = py::dict(),
      "The scene of a dict of tables ({'domain': {...}, ...}); `path` names it and anchors relative mesh files");
}

// `hpcontact advise` for Python: advice.csv's columns (written to out/advice.csv if given), the
// recommendation's scene edits, alpha_min.
py::tuple run_advice(const scene::Scene& scene, std::optional<double> alpha_min, const std::filesystem::path& out) {
  if (!out.empty()) io::check_output_directory(out);  // (advice.csv goes into out itself)
  const auto advice = python::run_interruptibly(
      [scene, alpha_min] { return studies::advise_pairing(scene, {.alpha_min = alpha_min}); });
  const auto table = studies::advice_table(advice);
  if (!out.empty()) {
    io::ensure_writable_directory(out);
    table.write(out / "advice.csv");
  }
  py::list edits;
  if (advice.recommended)
    for (const auto& edit : advice.candidates[*advice.recommended].edits) edits.append(edit);
  return py::make_tuple(columns_of(table), edits, advice.alpha_min);
}

// `hpcontact sweep` from Python: the paths of alpha.csv and verdicts.csv.
py::tuple run_sweep(const std::string& study, const std::filesystem::path& out, bool restart) {
  const auto alpha_csv = out / "alpha.csv";
  // Reading builds the levels' meshes (MPI): on the library thread too. The folder's lock is
  // held by the work, since an interrupted call returns before the work ends.
  const auto [outcome, fit_levels] = python::run_interruptibly([study, out, alpha_csv, restart] {
    const auto sweep = studies::read_stability_sweep(study);
    const auto lock = studies::open_sweep_folder(sweep, out, restart);
    return std::pair{studies::run_stability_sweep(sweep, alpha_csv, {}), sweep.fit_levels};
  });
  const auto verdicts = studies::fit_verdicts(outcome.rows, fit_levels);
  verdicts.write(out / "verdicts.csv");
  return py::make_tuple(alpha_csv.string(), (out / "verdicts.csv").string());
}

}  // namespace

PYBIND11_MODULE(_hpcontact, m) {
  m.doc() = "hpcontact: higher-order mixed FEM for contact problems and their inf-sup stability (compiled part)";
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const InputError& e) {
      PyErr_SetString(input_error.ptr(), e.what());
    } catch (const OutOfMemory& e) {
      PyErr_SetString(PyExc_MemoryError, e.what());
    }
  });
  python::bind_run_result(m);
  // On the thread that will run CHOLMOD and BLAS: libgomp's threads and OpenBLAS's buffer are its.
  python::run_interruptibly([] {
    reserve_library_buffers();
    return true;
  });
  session() = std::make_unique<PetscSession>(std::vector<std::string>{"hpcontact-python"}, false);
  // PETSc ends on the thread that started it, after the work still queued there.
  py::module_::import("atexit").attr("register")(py::cpp_function([] {
    py::gil_scoped_release release;
    python::post_to_library_thread([] { session().reset(); });
    python::stop_library_thread();
  }));

  bind_scenes(m);
  m.def(
      "run_scene",
      [](const scene::Scene& scene, const std::string& out) {
        if (!out.empty()) io::check_output_folder(out);  // before the work, as the command line does
        // What the run fills, owned by the work: an interrupted call returns before the work ends.
        struct Outputs {
          std::map<std::string, io::CsvTable> tables;
          std::map<std::string, io::VtuGrid> fields;
          driver::RunResult result;
        };
        auto outputs = std::make_shared<Outputs>();
        python::run_interruptibly([outputs, scene, out] {
          driver::SceneRunOptions options;
          options.out = out;
          options.write_files = !out.empty();
          options.tables = &outputs->tables;
          options.fields = &outputs->fields;
          outputs->result = driver::run_scene(scene, options);
          return true;
        });
        auto& [tables, fields, result] = *outputs;
        py::dict arrays, grids;
        for (const auto& [name, table] : tables) arrays[py::str(name)] = columns_of(table);
        for (const auto& [name, grid] : fields) grids[py::str(name)] = python::vtu_grid_arrays(grid);
        const auto summary = json_to_python(driver::summary_json(result));
        return py::make_tuple(std::move(result), summary, arrays, grids);
      },
      py::arg("scene"), py::arg("out") = "",
      "Runs the scene's effects: (RunResult, summary dict, {table name: {column: array}}, {solution name: "
      "{array name: array}}); writes files into `out` if given");
  m.def("run_sweep", &run_sweep, py::arg("study"), py::arg("out"), py::arg("restart") = false,
        "Runs a stability sweep into `out` (alpha.csv, resumable unless `restart`; verdicts.csv): the two file paths");
  m.def("run_advice", &run_advice, py::arg("scene"), py::arg("alpha_min") = py::none(),
        py::arg("out") = std::filesystem::path(),
        "The candidates of `hpcontact advise` as advice.csv's columns (written to out/advice.csv if given), the "
        "recommendation's scene edits, alpha_min");
  m.def("scene_keys", [] {
    py::list keys;
    for (const auto& key : scene::scene_keys())
      keys.append(py::dict(py::arg("key") = key.dotted(), py::arg("type") = key.type,
                           py::arg("default") = key.default_text, py::arg("allowed") = key.allowed,
                           py::arg("doc") = key.doc));
    return keys;
  });
}
