#pragma once
// Pressure-gradient models. All three reduce to the seed's eq. 3 for a smooth field on a regular lattice; they
// differ in what they do with particle disorder and free surfaces.
#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"

namespace slide {

enum class GradientModel {
  standard,   // seed eq. 3: (p_j - p_i)
  pmin,       // (p_j - p_min,i)
  symmetric,  // (p_i + p_j)
};

inline std::string_view to_string(GradientModel m) {
  switch (m) {
    case GradientModel::standard: return "standard";
    case GradientModel::pmin: return "pmin";
    case GradientModel::symmetric: return "symmetric";
  }
  return "?";
}

// Seed eq. 3 (Koshizuka & Oka 1996; Lee et al. 2008), the MPS gradient of any scalar phi:
//   grad phi_i = d / n0 * sum_{j != i} (phi_j - phi_i) / |r_ij|^2 * r_ij * W(|r_ij|),  r_ij = r_j - r_i.
// Exact for a linear field on a regular lattice away from boundaries. As a pressure gradient it lets a particle
// be pulled towards lower-pressure neighbours, which clusters particles (the seed's "interface instabilities").
template <int D, class Field>
Vec<D> mps_gradient(std::size_t i, const std::vector<Vec<D>>& x, const Field& phi, const NeighborList& nl,
                    double re, double n0) {
  Vec<D> g = Vec<D>::Zero();
  const double re2 = re * re;
  for (const std::uint32_t* p = nl.begin(i); p != nl.end(i); ++p) {
    const std::uint32_t j = *p;
    const Vec<D> rij = x[j] - x[i];
    const double r2 = rij.squaredNorm();
    if (r2 >= re2) continue;
    g += ((phi[j] - phi[i]) * kernel_weight(std::sqrt(r2), re) / r2) * rij;
  }
  return (D / n0) * g;
}

// Pressure gradient by model, over all neighbours within re.
//  * pmin (Koshizuka, Nobe & Oka 1998, Int. J. Numer. Meth. Fluids 26): p_i is replaced by the smallest pressure
//    among i and its neighbours, so every pair term is repulsive:
//      grad p_i = d / n0 * sum (p_j - p_min,i) / |r_ij|^2 * r_ij * W.
//  * symmetric (Oochi, Koshizuka & Sakai 2010; Tanaka & Masunaga 2010): the pair force is antisymmetric, so the
//    pressure forces conserve linear momentum exactly:
//      grad p_i = d / n0 * sum (p_i + p_j) / |r_ij|^2 * r_ij * W.
//    On a full regular lattice sum r_ij W / r^2 = 0, so it equals eq. 3 there.
template <int D, GradientModel M>
Vec<D> pressure_gradient_of(std::size_t i, const std::vector<Vec<D>>& x, const std::vector<double>& p,
                            const NeighborList& nl, double re, double n0) {
  const double re2 = re * re;
  double p_ref = p[i];
  if constexpr (M == GradientModel::pmin) {
    for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q)
      if (distance_squared<D>(x[*q], x[i]) < re2) p_ref = std::min(p_ref, p[*q]);
  }
  Vec<D> g = Vec<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    const Vec<D> rij = x[j] - x[i];
    const double r2 = rij.squaredNorm();
    if (r2 >= re2) continue;
    const double w = kernel_weight(std::sqrt(r2), re);
    double dp;
    if constexpr (M == GradientModel::symmetric)
      dp = p[i] + p[j];
    else
      dp = p[j] - p_ref;
    g += (dp * w / r2) * rij;
  }
  return (D / n0) * g;
}

template <int D>
Vec<D> pressure_gradient(GradientModel m, std::size_t i, const std::vector<Vec<D>>& x, const std::vector<double>& p,
                         const NeighborList& nl, double re, double n0) {
  switch (m) {
    case GradientModel::standard: return pressure_gradient_of<D, GradientModel::standard>(i, x, p, nl, re, n0);
    case GradientModel::pmin: return pressure_gradient_of<D, GradientModel::pmin>(i, x, p, nl, re, n0);
    case GradientModel::symmetric: return pressure_gradient_of<D, GradientModel::symmetric>(i, x, p, nl, re, n0);
  }
  return Vec<D>::Zero();
}

}  // namespace slide
