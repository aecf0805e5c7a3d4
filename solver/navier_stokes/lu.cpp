// The Jacobian's sparse LU plumbing: UMFPACK's error wording, triplets to compressed columns, and the
// nested-dissection order of the grid's unknowns, and OpenBLAS held to one thread around a factorisation.
#include "solver/navier_stokes/lu.hpp"

#include <dlfcn.h>
#include <umfpack.h>

#include <mutex>

#include <algorithm>
#include <stdexcept>

namespace magnus {

namespace {

/// Nested dissection of the box of nodes [i0, i1) × [j0, j1) of a grid with a 9-point stencil (George
/// 1973), or one that reaches wj columns either side in θ and wi rings either side in ξ: the two halves
/// either side of the middle line of the longer side (wj columns wide across θ, wi rings across ξ), then
/// that line; small boxes in natural order. `put` takes a node (i, j).
template <class Put>
void dissect(int i0, int i1, int j0, int j1, int wi, int wj, const Put& put) {
  if (i1 <= i0 || j1 <= j0) return;
  if ((i1 - i0) * (j1 - j0) <= 16) {
    for (int i = i0; i < i1; ++i)
      for (int j = j0; j < j1; ++j) put(i, j);
    return;
  }
  if (i1 - i0 >= j1 - j0) {
    const int s = std::min((i0 + i1) / 2, i1 - wi);
    dissect(i0, s, j0, j1, wi, wj, put), dissect(s + wi, i1, j0, j1, wi, wj, put);
    for (int i = s; i < s + wi; ++i)
      for (int j = j0; j < j1; ++j) put(i, j);
  } else {
    const int s = std::min((j0 + j1) / 2, j1 - wj);
    dissect(i0, i1, j0, s, wi, wj, put), dissect(i0, i1, s + wj, j1, wi, wj, put);
    for (int i = i0; i < i1; ++i)
      for (int j = s; j < s + wj; ++j) put(i, j);
  }
}

}  // namespace

std::vector<long> grid_order(int nr, int n, bool mirror, int theta_reach, int xi_reach) {
  const int wj = std::max(1, theta_reach), wi = std::max(1, xi_reach);
  std::vector<long> order;
  if (mirror) {
    const int m = n / 2 - 1;
    order.reserve(size_t(2) * nr * m);
    dissect(0, nr, 1, n / 2, wi, wj, [&](int i, int j) {
      const long u = 2 * (long(i) * m + j - 1);
      order.push_back(u), order.push_back(u + 1);
    });
    return order;
  }
  order.reserve(size_t(2) * nr * n + 1);
  auto put = [&](int i, int j) {
    const long u = 2 * (long(i) * n + j);
    order.push_back(u), order.push_back(u + 1);
  };
  dissect(0, nr, wj, n / 2, wi, wj, put);
  dissect(0, nr, n / 2 + wj, n, wi, wj, put);
  for (int j0 : {0, n / 2})
    for (int i = 0; i < nr; ++i)
      for (int j = j0; j < j0 + wj; ++j) put(i, j);
  order.push_back(2L * nr * n);  // Γ_R
  return order;
}

void triplet_pattern(long n, const std::vector<long>& ti, const std::vector<long>& tj, std::vector<long>& Ap,
                     std::vector<long>& Ai, std::vector<long>& map) {
  Ap.assign(size_t(n) + 1, 0);
  Ai.resize(ti.size());
  map.resize(ti.size());
  const long status = umfpack_dl_triplet_to_col(n, n, long(ti.size()), ti.data(), tj.data(), nullptr,
                                                Ap.data(), Ai.data(), nullptr, map.data());
  if (status != UMFPACK_OK) throw std::runtime_error(umfpack_error("triplet_to_col (assembly)", status));
  Ai.resize(size_t(Ap.back()));
}

void compress_triplets(long n, const std::vector<long>& ti, const std::vector<long>& tj, const std::vector<double>& tx,
                       std::vector<long>& Ap, std::vector<long>& Ai, std::vector<double>& Ax) {
  std::vector<long> map;
  triplet_pattern(n, ti, tj, Ap, Ai, map);
  Ax.assign(Ai.size(), 0.0);
  for (size_t t = 0; t < tx.size(); ++t) Ax[size_t(map[t])] += tx[t];
}

std::string umfpack_error(const char* what, long status) {
  std::string s =
      std::string("UMFPACK ") + what + " failed (status " + std::to_string(status);
  if (status == UMFPACK_WARNING_singular_matrix) s += ": the matrix is singular";
  if (status == UMFPACK_ERROR_out_of_memory) s += ": out of memory";
  return s + ")";
}

long symbolic_in_grid_order(long n, const std::vector<long>& q,
                            const std::function<long(const double*, const long*)>& analyse) {
  double control[UMFPACK_CONTROL];  // the real and complex defaults are the same
  umfpack_dl_defaults(control);
  long status = UMFPACK_ERROR_invalid_permutation;
  if (long(q.size()) == n) {
    control[UMFPACK_ORDERING] = UMFPACK_ORDERING_GIVEN;
    control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
    status = analyse(control, q.data());
  }
  if (status != UMFPACK_OK) {
    umfpack_dl_defaults(control);
    control[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
    status = analyse(control, nullptr);
  }
  if (status != UMFPACK_OK) {
    umfpack_dl_defaults(control);
    status = analyse(control, nullptr);
  }
  return status;
}

namespace {

/// How many SingleThreadBlas live, and the thread count the first one found (restored by the last).
std::mutex blas_mutex;
int blas_holders = 0;
int blas_saved = 1;

}  // namespace

SingleThreadBlas::SingleThreadBlas() {
  get_ = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  set_ = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!get_ || !set_) return;
  const std::lock_guard<std::mutex> lock(blas_mutex);
  if (blas_holders++ == 0) {
    blas_saved = get_();
    if (blas_saved != 1) set_(1);
  }
}

SingleThreadBlas::~SingleThreadBlas() {
  if (!get_ || !set_) return;
  const std::lock_guard<std::mutex> lock(blas_mutex);
  if (--blas_holders == 0 && blas_saved > 1) set_(blas_saved);
}

}  // namespace magnus
