#pragma once
// A block of 11^d fluid particles on the square (cubic) or, in 2-D, the hexagonal lattice, with its neighbour list and
// lattice constants: the fixture of the operator tests against exact answers (tests/test_operators.cpp,
// tests/test_rheology.cpp).
#include "fluid/kernel.hpp"
#include "fluid/lattice.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide::testing {

template <int D>
struct Lattice {
  static constexpr int side = 11;
  double dp = 0.1, re = 0.21;
  Particles<D> particles;
  NeighborList list;
  LatticeConstants constants;
  std::size_t centre = 0;

  // The square (cubic) lattice, or in 2-D the hexagonal one (fluid/lattice.hpp).
  explicit Lattice(LatticeKind kind = LatticeKind::square) {
    const int kmax = D == 3 ? side : 1;
    for (int k = 0; k < kmax; ++k)
      for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
          Vec<D> x;
          if constexpr (D == 2) {
            x = lattice_point(kind, dp, i, j);
          } else {
            x = Vec<D>(i * dp, j * dp, k * dp);
          }
          const std::size_t n = particles.add(x, Kind::fluid, 0, 1000.0, 1e-3);
          if (i == side / 2 && j == side / 2 && (D == 2 || k == side / 2)) centre = n;
        }
    NeighborGrid<D> grid(Vec<D>::Constant(-dp), Vec<D>::Constant((side + 2) * dp), re);
    grid.bin(particles.position);
    build_neighbor_list(grid, particles.position, re, list);
    constants = lattice_constants<D>(dp, re, kind);
  }
  // Particles whose whole kernel support lies inside the lattice.
  bool interior(std::size_t i) const {
    for (int k = 0; k < D; ++k)
      if (particles.position[i][k] < 3 * dp - 1e-9 || particles.position[i][k] > (side - 4) * dp + 1e-9) return false;
    return true;
  }
};

}  // namespace slide::testing
