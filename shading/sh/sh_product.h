// SH triple-product tensor Γ_ijk = ∫ y_i y_j y_k (sparse) and the truncated
// SH product (f*g)_i = Σ_jk Γ_ijk f_j g_k (commutative, NOT associative).
#pragma once

#include "shading/sh/sh_basis.h"

#include <vector>

namespace skylit::sh {

struct TripleEntry {
  int i, j, k;
  double value;
};

class TripleProduct {
 public:
  explicit TripleProduct(int order);
  int order() const { return order_; }
  // All non-zeros (every index permutation listed).
  const std::vector<TripleEntry>& entries() const { return entries_; }
  void product(std::span<const double> f, std::span<const double> g, std::span<double> out) const;
  Vec product(std::span<const double> f, std::span<const double> g) const;
  // M_f[i][j] = Σ_k Γ_ijk f_k (row-major n²×n², symmetric); f*g = M_f g.
  std::vector<double> matrix(std::span<const double> f) const;

 private:
  int order_;
  std::vector<TripleEntry> entries_;
};

// Cached tensor for an order (thread-safe, built once).
const TripleProduct& triple_product(int order);

}  // namespace skylit::sh
