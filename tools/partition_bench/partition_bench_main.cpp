// slide_partition_bench: how evenly, and at what cost in ghosts, the neighbour grid's cells are shared among N
// processes by the project's own recursive coordinate bisection (fluid/cell_partition.hpp) and by Zoltan's RCB, HSFC
// (Hilbert space-filling curve) and RIB (issue 32 asks for Zoltan: "measure and choose"). tools/bench --partition
// builds and runs it (only where Zoltan, Debian's libtrilinos-zoltan-dev, is installed: CMakeLists.txt).
//   slide_partition_bench SCENE.yaml TIMES [key.path=value ...]
// TIMES: comma-separated simulated times, ascending (0,0.1,0.25): the scene is built, then advanced to each in turn on
// this one process (OpenMP threads), and at each the partitions are measured. One JSON line per (time, method, N,
// tolerance) on standard output; progress on standard error.
//
// What is partitioned, and how each method sees it:
//  * the cells of the grid the step loop uses (Simulation::grid(): the domain's box, cell = the neighbour list's
//    radius), weighted by the owned real particles in each (fluid, wall and body particles alike: what
//    Domain::local_cell_weights counts; the periodic and mirror images are ghosts, not counted).
//  * own RCB: CellPartition<D>(cells, weights, N) over every cell, empty ones included (as Domain does).
//  * Zoltan: one object per non-empty cell (global id = the linear cell index), its coordinates the cell's centre
//    measured from the grid's lower corner (every method here is blind to a shift), its weight the particle count;
//    NUM_GLOBAL_PARTS = N on one process (MPI started as a singleton: mpi/mpi_communicator.hpp), RETURN_LISTS PARTS,
//    RCB_REUSE 0, KEEP_CUTS 0, DEBUG_LEVEL 0, REMAP 0, and IMBALANCE_TOL 1.0 and 1.05 (each a line). The empty cells
//    get no owner: a run would need the cuts kept (KEEP_CUTS 1, Zoltan_LB_Point_PP_Assign) to place particles that
//    move into them, which this measurement leaves out.
//
// What is measured for each partition:
//  * imbalance = the largest part's weight / the mean part's weight.
//  * ghosts: part p needs, as ghosts, every particle of a cell it does not own that lies within `reach` cells
//    (Chebyshev distance in cell indices) of a non-empty cell it owns (fluid/process_halo.hpp: a cell's particles go to
//    the owner of every cell within reach of it). Reported at the reach a run on several processes uses
//    (Simulation::prepare_processes: 1, or with mirrored wall pressure 1 + ceil(2 x the deepest boundary particle /
//    cell size)) and at reach 1: the total over parts, the part with the most ghosts (its ghosts, its owned weight and
//    their ratio) and the largest ghost/owned ratio of any part. Only non-empty owned cells count, so that own RCB
//    (which owns every cell) and Zoltan (non-empty cells only) are measured alike; for own RCB the line also has
//    `halo_rule`: the ghosts as ProcessHalo really sends them, an empty owned cell drawing its neighbours too.
//    Periodic and mirror images are ignored (a process would also hold the images of particles near a period's end or
//    a plane of symmetry; they do not depend on the partition much and are left out).
//  * time_us: the median of 5 calls of the whole partitioning (for Zoltan: create, set the parameters, partition, read
//    the parts back, free; the object list is made before the clock starts), microseconds, on this process.
//  * identical_maps: whether the 5 calls gave the same owner for every cell (they must: every process computes the
//    map itself, and a run's processes must agree).
#include <mpi.h>
#include <omp.h>
#include <zoltan.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cases/scene.hpp"
#include "coupling/advance.hpp"
#include "fluid/cell_partition.hpp"
#include "fluid/process_halo.hpp"
#include "mpi/mpi_communicator.hpp"

namespace {

constexpr int kCalls = 5;                  // timed calls per partition (median)
const std::vector<int> kParts = {2, 4, 8, 16, 64};
const std::vector<double> kTolerances = {1.0, 1.05};

// The cells' weights at one moment, and what the measures need of the grid.
template <int D>
struct CellWeights {
  std::array<int, D> cells{};
  double cell_size = 0.0;
  std::vector<std::int64_t> weight;   // per linear cell (x fastest)
  std::vector<std::size_t> nonempty;  // the linear indices of the cells with particles, ascending
  std::int64_t total = 0;
};

// The owned real particles per cell of the step loop's grid (Domain::local_cell_weights on one process).
template <int D>
CellWeights<D> cell_weights(const slide::Simulation<D>& sim) {
  const auto& grid = sim.grid();
  const auto& P = sim.particles();
  CellWeights<D> w;
  w.cells = grid.cells();
  w.cell_size = grid.cell_size();
  w.weight.assign(grid.total_cells(), 0);
  for (std::size_t i = 0; i < P.real_count(); ++i) ++w.weight[grid.linear(grid.cell_of(P.position[i]))];
  for (std::size_t c = 0; c < w.weight.size(); ++c)
    if (w.weight[c] > 0) w.nonempty.push_back(c);
  w.total = static_cast<std::int64_t>(P.real_count());
  return w;
}

// The halo's reach in cells on several processes, by Simulation::prepare_processes' rule: a boundary particle's mirror
// image lies twice its depth in front of it, and the fluid around the image must be held.
template <int D>
int halo_reach(const slide::Simulation<D>& sim) {
  if (sim.options.wall_pressure != slide::WallPressure::mirror) return 1;
  const auto& P = sim.particles();
  double deepest = 0.0;
  for (std::size_t i = 0; i < P.real_count(); ++i)
    if (P.kind[i] != slide::Kind::fluid) deepest = std::max(deepest, P.wall_depth[i]);
  return 1 + static_cast<int>(std::ceil(2.0 * deepest / sim.grid().cell_size()));
}

template <int D>
std::array<int, D> cell_coordinates(std::size_t linear, const std::array<int, D>& cells) {
  std::array<int, D> c{};
  for (int k = 0; k < D; ++k) {
    c[k] = static_cast<int>(linear % static_cast<std::size_t>(cells[k]));
    linear /= static_cast<std::size_t>(cells[k]);
  }
  return c;
}

template <int D>
std::size_t linear_index(const std::array<int, D>& c, const std::array<int, D>& cells) {
  std::size_t l = 0;
  for (int k = D - 1; k >= 0; --k) l = l * static_cast<std::size_t>(cells[k]) + static_cast<std::size_t>(c[k]);
  return l;
}


// ---- the methods: each returns the owner of every cell (-1: none) ----

using Owners = std::vector<int>;

template <int D>
Owners own_rcb(const CellWeights<D>& w, int parts) {
  return slide::CellPartition<D>(w.cells, w.weight, parts).owners();
}

// Zoltan's view of the cells: the non-empty ones as objects (local id = position in the list).
struct ZoltanObjects {
  int dimension = 0;
  std::vector<ZOLTAN_ID_TYPE> global_id;  // linear cell index
  std::vector<float> weight;
  std::vector<double> centre;  // dimension per object
};

template <int D>
ZoltanObjects zoltan_objects(const CellWeights<D>& w) {
  ZoltanObjects o;
  o.dimension = D;
  for (const std::size_t cell : w.nonempty) {
    o.global_id.push_back(static_cast<ZOLTAN_ID_TYPE>(cell));
    o.weight.push_back(static_cast<float>(w.weight[cell]));
    const auto c = cell_coordinates<D>(cell, w.cells);
    for (int k = 0; k < D; ++k) o.centre.push_back((c[k] + 0.5) * w.cell_size);
  }
  return o;
}

// Zoltan's query functions over ZoltanObjects (its C interface: a void* to the data).
int zoltan_count(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<int>(static_cast<const ZoltanObjects*>(data)->global_id.size());
}
void zoltan_list(void* data, int, int, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR lids, int wdim, float* weights, int* ierr) {
  const auto& o = *static_cast<const ZoltanObjects*>(data);
  for (std::size_t i = 0; i < o.global_id.size(); ++i) {
    gids[i] = o.global_id[i];
    lids[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    if (wdim == 1) weights[i] = o.weight[i];
  }
  *ierr = ZOLTAN_OK;
}
int zoltan_dimension(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<const ZoltanObjects*>(data)->dimension;
}
void zoltan_coordinates(void* data, int, int, int count, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR lids, int dim, double* out,
                        int* ierr) {
  const auto& o = *static_cast<const ZoltanObjects*>(data);
  for (int i = 0; i < count; ++i)
    for (int k = 0; k < dim; ++k) out[i * dim + k] = o.centre[lids[i] * static_cast<std::size_t>(dim) + k];
  *ierr = ZOLTAN_OK;
}

void zoltan_check(int code, const char* what) {
  if (code != ZOLTAN_OK) throw std::runtime_error(fmt::format("Zoltan: {} returned {}", what, code));
}

void zoltan_parameters(Zoltan_Struct* zz, const std::string& method, int parts, double tolerance) {
  const std::vector<std::pair<const char*, std::string>> params = {
      {"DEBUG_LEVEL", "0"}, {"LB_METHOD", method}, {"LB_APPROACH", "PARTITION"},
      {"NUM_GID_ENTRIES", "1"}, {"NUM_LID_ENTRIES", "1"}, {"OBJ_WEIGHT_DIM", "1"},
      {"RETURN_LISTS", "PARTS"}, {"NUM_GLOBAL_PARTS", std::to_string(parts)},
      {"IMBALANCE_TOL", fmt::format("{}", tolerance)}, {"RCB_REUSE", "0"}, {"KEEP_CUTS", "0"}, {"REMAP", "0"}};
  for (const auto& [name, value] : params) zoltan_check(Zoltan_Set_Param(zz, name, value.c_str()), name);
}

// One Zoltan partition of the objects into `parts`, as the owner of every cell of a grid of `cells` cells.
Owners zoltan_partition(const ZoltanObjects& objects, std::size_t cells, const std::string& method, int parts,
                        double tolerance) {
  Zoltan_Struct* zz = Zoltan_Create(MPI_COMM_WORLD);
  if (zz == nullptr) throw std::runtime_error("Zoltan_Create failed");
  void* data = const_cast<ZoltanObjects*>(&objects);
  Owners owner(cells, -1);
  try {
    zoltan_parameters(zz, method, parts, tolerance);
    Zoltan_Set_Num_Obj_Fn(zz, zoltan_count, data);
    Zoltan_Set_Obj_List_Fn(zz, zoltan_list, data);
    Zoltan_Set_Num_Geom_Fn(zz, zoltan_dimension, data);
    Zoltan_Set_Geom_Multi_Fn(zz, zoltan_coordinates, data);
    int changes = 0, gid_entries = 0, lid_entries = 0, imports = 0, exports = 0;
    ZOLTAN_ID_PTR import_gids = nullptr, import_lids = nullptr, export_gids = nullptr, export_lids = nullptr;
    int *import_procs = nullptr, *import_parts = nullptr, *export_procs = nullptr, *export_parts = nullptr;
    zoltan_check(Zoltan_LB_Partition(zz, &changes, &gid_entries, &lid_entries, &imports, &import_gids, &import_lids,
                                     &import_procs, &import_parts, &exports, &export_gids, &export_lids, &export_procs,
                                     &export_parts),
                 "Zoltan_LB_Partition");
    // RETURN_LISTS PARTS: the export lists hold every object with its part.
    const bool every = static_cast<std::size_t>(exports) == objects.global_id.size();
    for (int i = 0; every && i < exports; ++i) owner[export_gids[i]] = export_parts[i];
    Zoltan_LB_Free_Part(&import_gids, &import_lids, &import_procs, &import_parts);
    Zoltan_LB_Free_Part(&export_gids, &export_lids, &export_procs, &export_parts);
    if (!every) throw std::runtime_error(fmt::format("Zoltan returned {} of {} objects' parts", exports,
                                                     objects.global_id.size()));
  } catch (...) {
    Zoltan_Destroy(&zz);
    throw;
  }
  Zoltan_Destroy(&zz);
  return owner;
}

// ---- the measures ----

// Each part's weight: the particles of the cells it owns.
template <int D>
std::vector<std::int64_t> part_weights(const CellWeights<D>& w, const Owners& owner, int parts) {
  std::vector<std::int64_t> sum(static_cast<std::size_t>(parts), 0);
  for (const std::size_t c : w.nonempty) sum[static_cast<std::size_t>(owner[c])] += w.weight[c];
  return sum;
}

// largest / mean = largest x parts / total.
double imbalance(const std::vector<std::int64_t>& part_weight, std::int64_t total) {
  const std::int64_t most = *std::max_element(part_weight.begin(), part_weight.end());
  return total == 0 ? 1.0 : double(most) * double(part_weight.size()) / double(total);
}

// Each part's ghosts: cell c's particles go to the owner of every cell within `reach` of c other than c's own owner
// (ProcessHalo::set_partition's needers, turned around: c is near q exactly when q is near c). `empty_cells_draw`:
// an empty owned cell draws its neighbours too (the halo's rule); otherwise only non-empty owned cells do.
template <int D>
std::vector<std::int64_t> part_ghosts(const CellWeights<D>& w, const Owners& owner, int parts, int reach,
                                      bool empty_cells_draw) {
  std::vector<std::int64_t> ghosts(static_cast<std::size_t>(parts), 0);
  std::vector<int> near;
  for (const std::size_t c : w.nonempty) {
    near.clear();
    slide::ProcessHalo<D>::for_each_cell_near(cell_coordinates<D>(c, w.cells), w.cells, reach,
                                              [&](const std::array<int, D>& cell) {
      const std::size_t q = linear_index<D>(cell, w.cells);
      if (owner[q] >= 0 && owner[q] != owner[c] && (empty_cells_draw || w.weight[q] > 0)) near.push_back(owner[q]);
    });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (const int p : near) ghosts[static_cast<std::size_t>(p)] += w.weight[c];
  }
  return ghosts;
}

// The ghosts' summary as JSON: total, the part with the most (its ghosts, owned weight, their ratio; the lowest part
// on a tie) and the largest ghost/owned ratio of any part with particles.
std::string ghost_json(const std::vector<std::int64_t>& ghosts, const std::vector<std::int64_t>& owned, int reach) {
  std::int64_t total = 0;
  std::size_t most = 0;
  double worst = 0.0;
  for (std::size_t p = 0; p < ghosts.size(); ++p) {
    total += ghosts[p];
    if (ghosts[p] > ghosts[most]) most = p;
    if (owned[p] > 0) worst = std::max(worst, double(ghosts[p]) / double(owned[p]));
  }
  const double ratio = owned[most] > 0 ? double(ghosts[most]) / double(owned[most]) : 0.0;
  return fmt::format("{{\"reach\": {}, \"total\": {}, \"max\": {}, \"max_part_owned\": {}, \"max_over_owned\": {:.4f}, "
                     "\"worst_ratio\": {:.4f}}}",
                     reach, total, ghosts[most], owned[most], ratio, worst);
}

// Calls `partition` kCalls times: the median time in microseconds, the first map, and whether every map was the same.
struct Timed {
  double median_us = 0.0;
  Owners owner;
  bool identical = true;
};
Timed timed(const std::function<Owners()>& partition) {
  Timed t;
  std::vector<double> us;
  for (int call = 0; call < kCalls; ++call) {
    const auto start = std::chrono::steady_clock::now();
    Owners o = partition();
    us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
    if (call == 0) t.owner = std::move(o);
    else t.identical = t.identical && o == t.owner;
  }
  std::sort(us.begin(), us.end());
  t.median_us = us[us.size() / 2];
  return t;
}

// What every line of one moment shares.
struct Moment {
  std::string scene, overrides;
  int dimension = 0;
  double time = 0.0;
  long steps = 0;
  int reach = 1;
};

// One JSON line: the moment, the method, and the measures of its partition into `parts`.
template <int D>
void report(const Moment& m, const CellWeights<D>& w, const std::string& method, std::optional<double> tolerance,
            int parts, const Timed& t) {
  const auto owned = part_weights<D>(w, t.owner, parts);
  std::string ghosts = ghost_json(part_ghosts<D>(w, t.owner, parts, m.reach, false), owned, m.reach);
  if (m.reach != 1) ghosts += ", " + ghost_json(part_ghosts<D>(w, t.owner, parts, 1, false), owned, 1);
  std::string halo_rule;
  if (method == "own_rcb")
    halo_rule = ", \"halo_rule\": " + ghost_json(part_ghosts<D>(w, t.owner, parts, m.reach, true), owned, m.reach);
  std::string cells;
  for (int k = 0; k < D; ++k) cells += fmt::format("{}{}", k ? ", " : "", w.cells[k]);
  std::cout << fmt::format(
                   "{{\"scene\": \"{}\", \"overrides\": \"{}\", \"dimension\": {}, \"t\": {}, \"steps\": {}, "
                   "\"particles\": {}, \"cells\": [{}], \"nonempty_cells\": {}, \"method\": \"{}\", "
                   "\"imbalance_tol\": {}, \"parts\": {}, \"imbalance\": {:.4f}, \"largest_part\": {}, "
                   "\"ghosts\": [{}]{}, \"time_us\": {:.1f}, \"identical_maps\": {}}}\n",
                   m.scene, m.overrides, m.dimension, m.time, m.steps, w.total, cells, w.nonempty.size(), method,
                   tolerance ? fmt::format("{}", *tolerance) : "null", parts, imbalance(owned, w.total),
                   *std::max_element(owned.begin(), owned.end()), ghosts, halo_rule, t.median_us,
                   t.identical ? "true" : "false")
            << std::flush;
}

// Every method at every part count, at one moment.
template <int D>
void measure(const Moment& m, const CellWeights<D>& w) {
  const ZoltanObjects objects = zoltan_objects<D>(w);
  for (const int parts : kParts) {
    if (w.nonempty.size() < static_cast<std::size_t>(parts)) continue;
    report<D>(m, w, "own_rcb", std::nullopt, parts, timed([&] { return own_rcb<D>(w, parts); }));
    for (const char* method : {"RCB", "HSFC", "RIB"})
      for (const double tol : kTolerances)
        report<D>(m, w, fmt::format("zoltan_{}", method), tol, parts,
                  timed([&] { return zoltan_partition(objects, w.weight.size(), method, parts, tol); }));
  }
}

std::vector<double> parse_times(const std::string& text) {
  std::vector<double> times;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) times.push_back(std::stod(item));
  if (times.empty() || !std::is_sorted(times.begin(), times.end()))
    throw std::invalid_argument("TIMES: comma-separated times in ascending order, e.g. 0,0.1,0.25");
  return times;
}

template <int D>
int bench(const std::filesystem::path& scene_file, const std::vector<double>& times,
          const std::vector<std::string>& overrides) {
  auto scene = slide::cases::build_scene<D>(slide::cases::load_scene(scene_file, overrides), scene_file.stem().string(),
                                            scene_file.parent_path());
  slide::Simulation<D>& sim = *scene->simulation;
  sim.initialise();
  Moment m;
  m.scene = scene_file.stem().string();
  for (const auto& o : overrides) m.overrides += (m.overrides.empty() ? "" : " ") + o;
  m.dimension = D;
  for (const double t : times) {
    std::cerr << fmt::format("slide_partition_bench: {} to t = {} s ({} threads)\n", m.scene, t, omp_get_max_threads());
    const auto result = slide::advance<D>(sim, t);
    if (result.instability) throw std::runtime_error(fmt::format("the run went unstable before t = {} s", t));
    m.time = t;
    m.steps = sim.step_count();
    m.reach = halo_reach<D>(sim);
    measure<D>(m, cell_weights<D>(sim));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 3) {
      std::cerr << "usage: slide_partition_bench SCENE.yaml TIMES [key.path=value ...]   (TIMES: e.g. 0,0.1,0.25)\n";
      return 2;
    }
    slide::mpi::MpiSession mpi(argc, argv);  // Zoltan needs MPI; one process (a singleton without mpirun)
    float version = 0.0f;
    zoltan_check(Zoltan_Initialize(argc, argv, &version), "Zoltan_Initialize");
    const std::filesystem::path scene = argv[1];
    const std::vector<double> times = parse_times(argv[2]);
    const std::vector<std::string> overrides(argv + 3, argv + argc);
    const YAML::Node resolved = slide::cases::load_scene(scene, overrides);
    return slide::cases::scene_dimension(resolved) == 3 ? bench<3>(scene, times, overrides)
                                                        : bench<2>(scene, times, overrides);
  } catch (const std::exception& e) {
    std::cerr << "slide_partition_bench: " << e.what() << "\n";
    return 1;
  }
}
