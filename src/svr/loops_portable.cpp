// The portable table of the SVR engine's inner loops (loops.hpp): the functions of
// loops_scalar.hpp, for any processor.
#include "svr/loops.hpp"
#include "svr/loops_scalar.hpp"

namespace fogdrift::svr::detail {

float exp_to_float(double x) {
  return static_cast<float>(scalar::exp_core(x));
}

float kernel_exp(float y) {
  return scalar::kernel_exp(y);
}

const Loops& portable_loops() {
  static constexpr Loops kTable{
      .isa = Isa::portable,
      .libsvm_rbf_row = scalar::libsvm_rbf_row,
      .rbf_row = scalar::rbf_row,
      .rbf_rows = scalar::rbf_rows,
      .linear_row = scalar::linear_row,
      .distance_row = scalar::distance_row,
      .rbf_row_from_distances = scalar::rbf_row_from_distances,
      .update_gradient = scalar::update_gradient,
      .add_scaled = scalar::add_scaled,
      .add_row = scalar::add_row,
      .select_i = scalar::select_i,
      .select_j = scalar::select_j,
      .select_up = scalar::select_up,
      .update_and_select_up = scalar::update_and_select_up,
      .conjugate_update_and_select_up = scalar::conjugate_update_and_select_up,
      .select_low = scalar::select_low,
  };
  return kTable;
}

}  // namespace fogdrift::svr::detail
