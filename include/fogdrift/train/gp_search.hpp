// Choosing a Gaussian process's hyperparameters by grouped cross-validation (docs/gp.md,
// "Choosing the hyperparameters"), through the search every tuned method uses (opt/).
//
// The posterior mean (gp.hpp, eq. 2) depends on ℓ and on λ = σn²/s² alone:
//   f̄(x) = Σ_i α'_i · exp(−|x − p_i|² / 2ℓ²),  α' = (E + λ I)⁻¹ y,  E_ij = exp(−|p_i − p_j|² / 2ℓ²)
// so the search chooses (log10 ℓ, log10 λ), as the SVR's tuner chooses (log10 C, log10 σ), by the
// RMSE on the held-out rows of folds of whole recordings, each fold's GP fitted on at most
// `max_points` of its training rows and scored on at most `max_points` of its held-out rows. The
// scale then follows from the likelihood, whose maximum over s² for a fixed E + λI is closed:
//   s² = yᵀ (E + λ I)⁻¹ y / n                                        (docs/gp.md eq. 7)
// and σn² = λ s². Every fitness is a deterministic function of its point, so a seed gives one
// model whatever the thread count. Racing stops a candidate once its squared errors on the
// folds so far exceed the best complete candidate's of the batches before (a bound that does not
// depend on the order a batch runs in): such a candidate cannot be the best, and its fitness is
// then the RMSE of its errors so far, a lower bound above the best's.
#pragma once

#include <span>

#include "fogdrift/opt/optimizer.hpp"
#include "fogdrift/regress/gp.hpp"
#include "fogdrift/train/tune.hpp"

namespace fogdrift {

class ThreadPool;

struct GpSearch {
  GpFit fit;            ///< the GP of the best (ℓ, λ), fitted on the rows `all` keeps
  opt::Summary search;  ///< the optimizer's run; its best fitness is the folds' RMSE
};

/// Searches (ℓ, λ) in options.box by the RMSE over `splits` (scaled folds), then fits the GP of
/// the best on gp_rows(all.rows, options.max_points) of `all` (every training row, scaled).
/// Throws OptionError for options validate(GpOptions) or the optimizer refuses.
GpSearch search_gp(std::span<const tune::ScaledSplit> splits, const Data& all,
                   const GpOptions& options, const opt::OptimizerOptions& optimizer,
                   ThreadPool* pool = nullptr);

}  // namespace fogdrift
