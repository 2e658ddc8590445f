// gmsh_api::Session: libgmsh's C API resolved at run time.
#include "mesh/gmsh_api.hpp"

#include <dlfcn.h>
#include <fmt/format.h>
#include <gmshc.h>  // prototypes only: the functions are resolved with dlsym

#include "core/error.hpp"

namespace hpcontact::mesh::gmsh_api {
namespace {

// The C functions used, resolved once.
struct Library {
  decltype(&::gmshFree) free = nullptr;
  decltype(&::gmshInitialize) initialize = nullptr;
  decltype(&::gmshFinalize) finalize = nullptr;
  decltype(&::gmshOptionSetNumber) set_number = nullptr;
  decltype(&::gmshOptionGetNumber) get_number = nullptr;
  decltype(&::gmshModelMeshGenerate) generate = nullptr;
  decltype(&::gmshClear) clear = nullptr;
  decltype(&::gmshOpen) open = nullptr;
  decltype(&::gmshLoggerGetLastError) last_error = nullptr;
  decltype(&::gmshModelGetDimension) dimension = nullptr;
  decltype(&::gmshModelMeshGetElements) elements = nullptr;
  decltype(&::gmshModelMeshGetNodes) nodes = nullptr;
  decltype(&::gmshModelMeshGetElementProperties) element_properties = nullptr;
  decltype(&::gmshModelGetPhysicalGroups) physical_groups = nullptr;
  decltype(&::gmshModelGetPhysicalName) physical_name = nullptr;
  decltype(&::gmshModelGetEntitiesForPhysicalGroup) entities = nullptr;
  decltype(&::gmshModelGetEntities) all_entities = nullptr;
  decltype(&::gmshModelGetType) entity_type = nullptr;
  decltype(&::gmshModelGetParametrization) parametrization = nullptr;
  decltype(&::gmshModelGetValue) value = nullptr;
  decltype(&::gmshModelGetBoundingBox) bounding_box = nullptr;

  void start() const {
    int ierr = 0;
    initialize(0, nullptr, 0, &ierr);
    set_number("General.Terminal", 0, &ierr);
  }
};

template <typename Function>
void resolve(void* handle, const char* name, Function& out) {
  out = reinterpret_cast<Function>(dlsym(handle, name));
  if (!out) throw InputError(fmt::format("the Gmsh library lacks the function {} (Gmsh 4.8 or newer is needed)", name));
}

Library load() {
  void* handle = nullptr;
  std::string errors;
  for (const char* name : {HPCONTACT_GMSH_LIBRARY, "libgmsh.so.4.8", "libgmsh.so"}) {
    handle = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (handle) break;
    errors += fmt::format("\n  {}", dlerror());
  }
  if (!handle)
    throw InputError(
        "reading a Gmsh mesh file needs the Gmsh library (Debian package libgmsh4.8, installed with "
        "libgmsh-dev), which could not be loaded:" +
        errors);
  Library l;
  resolve(handle, "gmshFree", l.free);
  resolve(handle, "gmshInitialize", l.initialize);
  resolve(handle, "gmshFinalize", l.finalize);
  resolve(handle, "gmshOptionSetNumber", l.set_number);
  resolve(handle, "gmshOptionGetNumber", l.get_number);
  resolve(handle, "gmshModelMeshGenerate", l.generate);
  resolve(handle, "gmshClear", l.clear);
  resolve(handle, "gmshOpen", l.open);
  resolve(handle, "gmshLoggerGetLastError", l.last_error);
  resolve(handle, "gmshModelGetDimension", l.dimension);
  resolve(handle, "gmshModelMeshGetElements", l.elements);
  resolve(handle, "gmshModelMeshGetNodes", l.nodes);
  resolve(handle, "gmshModelMeshGetElementProperties", l.element_properties);
  resolve(handle, "gmshModelGetPhysicalGroups", l.physical_groups);
  resolve(handle, "gmshModelGetPhysicalName", l.physical_name);
  resolve(handle, "gmshModelGetEntitiesForPhysicalGroup", l.entities);
  resolve(handle, "gmshModelGetEntities", l.all_entities);
  resolve(handle, "gmshModelGetType", l.entity_type);
  resolve(handle, "gmshModelGetParametrization", l.parametrization);
  resolve(handle, "gmshModelGetValue", l.value);
  resolve(handle, "gmshModelGetBoundingBox", l.bounding_box);
  l.start();
  return l;
}

std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Loaded under the mutex by the first Session.
const Library& library() {
  static const Library loaded = load();
  return loaded;
}

// Gmsh's last error, freed.
std::string last_error() {
  char* text = nullptr;
  int ierr = 0;
  library().last_error(&text, &ierr);
  std::string out = text ? text : "";
  library().free(text);
  return out;
}

// A failed call: Gmsh's message. Queries on a model that was read never fail; reading may.
void check(int ierr, const char* what) {
  if (ierr != 0) throw InputError(fmt::format("Gmsh: {} failed: {}", what, last_error()));
}

template <typename T>
std::vector<T> take(T* data, std::size_t n) {
  std::vector<T> out(data, data + n);
  library().free(data);
  return out;
}

}  // namespace

Session::Session() : lock_(gmsh_mutex()) { library(); }

Session::~Session() = default;

// After an error inside a reader (or the mesher) Gmsh ignores later files until it is started
// afresh: restart it, then report.
[[noreturn]] void fail(const std::string& path, const char* what) {
  const std::string error = last_error();
  int ierr = 0;
  library().finalize(&ierr);
  library().start();
  throw InputError(fmt::format("{}: Gmsh cannot {}: {}", path, what, error.empty() ? "unknown error" : error));
}

void Session::open(const std::string& path) {
  const Library& l = library();
  int ierr = 0;
  // Gmsh started afresh: every option at its default, whatever an earlier file set.
  l.finalize(&ierr);
  l.start();
  l.open(path.c_str(), &ierr);
  if (ierr != 0) fail(path, "read the file");
}

namespace {

// Gmsh's mesher runs in an OpenMP region: an error it throws there (General.AbortOnError >= 2,
// the API's setting) ends the process. With 0 it logs the error and goes on; the log tells. The
// setting is restored after: the readers of open() report their errors by it.
void run_mesher(const std::string& path, int dimension) {
  const Library& l = library();
  int ierr = 0;
  double abort_on_error = 0.0;
  l.get_number("General.AbortOnError", &abort_on_error, &ierr);
  l.set_number("General.AbortOnError", 0.0, &ierr);
  const std::string error_before = last_error();
  int meshed = 0;
  l.generate(dimension, &meshed);
  const std::string error_after = last_error();
  l.set_number("General.AbortOnError", abort_on_error, &ierr);
  if (meshed != 0 || (!error_after.empty() && error_after != error_before)) fail(path, "mesh the geometry");
}

}  // namespace

void Session::generate(const std::string& path, std::optional<double> max_size, bool quadrilaterals) {
  const Library& l = library();
  int ierr = 0;
  // Curved boundaries come from the geometry itself (curve_points), so first-order cells suffice.
  const double recombine = quadrilaterals ? 1.0 : 0.0;
  for (const auto& [name, value] : {std::pair{"Mesh.RecombineAll", recombine},
                                    {"Mesh.Algorithm", 6.0},
                                    {"Mesh.SubdivisionAlgorithm", recombine},
                                    {"Mesh.ElementOrder", 1.0}})
    l.set_number(name, value, &ierr);
  // (reset without a size: Gmsh's options outlive the model, and a size of an earlier file would stay)
  l.set_number("Mesh.MeshSizeMax", max_size ? *max_size : 1e22, &ierr);
  run_mesher(path, 2);
}

void Session::generate_volume(const std::string& path, std::optional<double> max_size) {
  int ierr = 0;
  if (max_size) library().set_number("Mesh.MeshSizeMax", *max_size, &ierr);
  run_mesher(path, 3);
}

std::array<double, 6> Session::bounding_box() const {
  double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
  int ierr = 0;
  library().bounding_box(-1, -1, &x0, &y0, &z0, &x1, &y1, &z1, &ierr);
  check(ierr, "getBoundingBox");
  return {x0, y0, z0, x1, y1, z1};
}

int Session::dimension() const {
  int ierr = 0;
  const int dim = library().dimension(&ierr);
  check(ierr, "getDimension");
  return dim;
}

ElementBlocks Session::elements(int dim, int tag) const {
  int* types = nullptr;
  std::size_t n_types = 0, *tags_n = nullptr, tags_nn = 0, *nodes_n = nullptr, nodes_nn = 0;
  std::size_t **tags = nullptr, **nodes = nullptr;
  int ierr = 0;
  library().elements(&types, &n_types, &tags, &tags_n, &tags_nn, &nodes, &nodes_n, &nodes_nn, dim, tag, &ierr);
  check(ierr, "getElements");
  ElementBlocks out;
  out.types = take(types, n_types);
  for (std::size_t b = 0; b < tags_nn; ++b) out.tags.push_back(take(tags[b], tags_n[b]));
  for (std::size_t b = 0; b < nodes_nn; ++b) out.nodes.push_back(take(nodes[b], nodes_n[b]));
  library().free(tags);
  library().free(tags_n);
  library().free(nodes);
  library().free(nodes_n);
  return out;
}

void Session::nodes(std::vector<std::size_t>& tags, std::vector<double>& coordinates) const {
  std::size_t *tag_data = nullptr, n_tags = 0, n_coordinates = 0, n_parametric = 0;
  double *coordinate_data = nullptr, *parametric = nullptr;
  int ierr = 0;
  library().nodes(&tag_data, &n_tags, &coordinate_data, &n_coordinates, &parametric, &n_parametric, -1, -1, 0, 0,
                  &ierr);
  check(ierr, "getNodes");
  tags = take(tag_data, n_tags);
  coordinates = take(coordinate_data, n_coordinates);
  library().free(parametric);
}

ElementType Session::element_type(int type) const {
  char* name = nullptr;
  int dim = 0, order = 0, n_nodes = 0, n_primary = 0, ierr = 0;
  double* coordinates = nullptr;
  std::size_t n_coordinates = 0;
  library().element_properties(type, &name, &dim, &order, &n_nodes, &coordinates, &n_coordinates, &n_primary, &ierr);
  check(ierr, "getElementProperties");
  ElementType out{name ? name : "", order};
  library().free(name);
  library().free(coordinates);
  return out;
}

std::vector<std::pair<int, int>> Session::physical_groups(int dim) const {
  int* dim_tags = nullptr;
  std::size_t n = 0;
  int ierr = 0;
  library().physical_groups(&dim_tags, &n, dim, &ierr);
  check(ierr, "getPhysicalGroups");
  const std::vector<int> flat = take(dim_tags, n);
  std::vector<std::pair<int, int>> out;
  for (std::size_t k = 0; k + 1 < flat.size(); k += 2) out.emplace_back(flat[k], flat[k + 1]);
  return out;
}

std::string Session::physical_name(int dim, int tag) const {
  char* name = nullptr;
  int ierr = 0;
  library().physical_name(dim, tag, &name, &ierr);
  check(ierr, "getPhysicalName");
  std::string out = name ? name : "";
  library().free(name);
  return out;
}

std::vector<int> Session::entities_of_physical_group(int dim, int tag) const {
  int* tags = nullptr;
  std::size_t n = 0;
  int ierr = 0;
  library().entities(dim, tag, &tags, &n, &ierr);
  check(ierr, "getEntitiesForPhysicalGroup");
  return take(tags, n);
}

std::vector<int> Session::curves() const {
  int* dim_tags = nullptr;
  std::size_t n = 0;
  int ierr = 0;
  library().all_entities(&dim_tags, &n, 1, &ierr);
  check(ierr, "getEntities");
  const std::vector<int> flat = take(dim_tags, n);
  std::vector<int> out;
  for (std::size_t k = 1; k < flat.size(); k += 2) out.push_back(flat[k]);
  return out;
}

std::string Session::curve_type(int tag) const {
  char* type = nullptr;
  int ierr = 0;
  library().entity_type(1, tag, &type, &ierr);
  check(ierr, "getType");
  std::string out = type ? type : "";
  library().free(type);
  return out;
}

std::unordered_map<std::size_t, double> Session::curve_node_parameters(int tag) const {
  std::size_t *tag_data = nullptr, n_tags = 0, n_coordinates = 0, n_parametric = 0;
  double *coordinate_data = nullptr, *parametric = nullptr;
  int ierr = 0;
  library().nodes(&tag_data, &n_tags, &coordinate_data, &n_coordinates, &parametric, &n_parametric, 1, tag, 1, 1,
                  &ierr);
  check(ierr, "getNodes");
  const auto tags = take(tag_data, n_tags);
  const auto u = take(parametric, n_parametric);
  library().free(coordinate_data);
  HPC_VERIFY(u.size() == tags.size(), "one parameter per node of a curve");
  std::unordered_map<std::size_t, double> out;
  for (std::size_t k = 0; k < tags.size(); ++k) out[tags[k]] = u[k];
  return out;
}

std::vector<double> Session::curve_points(int tag, const std::vector<double>& parameters) const {
  std::vector<double> u = parameters;
  double* xyz = nullptr;
  std::size_t n = 0;
  int ierr = 0;
  library().value(1, tag, u.data(), u.size(), &xyz, &n, &ierr);
  check(ierr, "getValue");
  return take(xyz, n);
}

}  // namespace hpcontact::mesh::gmsh_api
