// slide_mpi_bench: one scene's step loop on the processes mpirun starts (or one process without it), timed, with what
// the exchanges between processes cost (fluid/domain.hpp, CommunicationCost). tools/bench --mpi runs it; one JSON
// line on standard output from process 0.
//   slide_mpi_bench SCENE.yaml END_TIME [key.path=value ...]
#include <omp.h>

#include <chrono>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cases/scene.hpp"
#include "coupling/advance.hpp"
#include "mpi/mpi_communicator.hpp"

namespace {

template <int D>
int bench(const std::filesystem::path& scene_file, double end_time, const std::vector<std::string>& overrides,
          std::shared_ptr<const slide::Communicator> comm) {
  using Clock = std::chrono::steady_clock;
  const auto setup_start = Clock::now();
  auto scene = slide::cases::build_scene<D>(slide::cases::load_scene(scene_file, overrides), scene_file.stem().string(),
                                            scene_file.parent_path());
  slide::Simulation<D>& sim = *scene->simulation;
  sim.set_communicator(comm);
  sim.initialise();
  const auto loop_start = Clock::now();
  const auto result = slide::advance<D>(sim, end_time);
  const double loop = std::chrono::duration<double>(Clock::now() - loop_start).count();
  const double setup = std::chrono::duration<double>(loop_start - setup_start).count();
  const auto& cost = sim.domain().communication_cost();
  const std::vector<double> all = slide::gather_on_first(
      *comm, {double(sim.particles().real_count()), double(sim.particles().ghost_count()), loop, cost.halo_seconds,
              cost.rebuild_seconds, cost.reduction_seconds, cost.bytes_sent});
  if (comm->rank() != 0) return result.instability ? 3 : 0;
  const long steps = sim.step_count();
  std::string per;
  double owned = 0.0;
  for (std::size_t r = 0; r * 7 < all.size(); ++r) {
    const double* v = &all[r * 7];
    owned += v[0];
    per += fmt::format("{}{{\"owned\": {:.0f}, \"ghosts\": {:.0f}, \"loop_s\": {:.4f}, \"halo_s\": {:.4f}, "
                       "\"rebuild_s\": {:.4f}, \"reduction_s\": {:.4f}, \"bytes_sent_per_step\": {:.0f}}}",
                       r ? ", " : "", v[0], v[1], v[2], v[3], v[4], v[5], v[6] / double(steps));
  }
  std::cout << fmt::format("{{\"processes\": {}, \"threads\": {}, \"particles\": {:.0f}, \"steps\": {}, "
                           "\"setup_s\": {:.3f}, \"loop_s\": {:.4f}, \"repartitions\": {}, \"unstable\": {}, "
                           "\"per_process\": [{}]}}\n",
                           comm->size(), omp_get_max_threads(), owned, steps, setup, loop,
                           sim.domain().repartitions(), result.instability ? "true" : "false", per);
  return result.instability ? 3 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::optional<slide::mpi::MpiSession> mpi;
    if (slide::mpi::launched_by_mpi()) mpi.emplace(argc, argv);
    if (argc < 3) {
      std::cerr << "usage: slide_mpi_bench SCENE.yaml END_TIME [key.path=value ...]\n";
      return 2;
    }
    std::shared_ptr<const slide::Communicator> comm =
        mpi ? mpi->world() : std::make_shared<slide::SerialCommunicator>();
    const std::vector<std::string> overrides(argv + 3, argv + argc);
    const std::filesystem::path scene = argv[1];
    const double end_time = std::stod(argv[2]);
    const YAML::Node resolved = slide::cases::load_scene(scene, overrides);
    return slide::cases::scene_dimension(resolved) == 3 ? bench<3>(scene, end_time, overrides, comm)
                                                        : bench<2>(scene, end_time, overrides, comm);
  } catch (const std::exception& e) {
    std::cerr << "slide_mpi_bench: " << e.what() << "\n";
    return 1;
  }
}
