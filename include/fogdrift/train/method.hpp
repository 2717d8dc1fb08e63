// A training method is a regressor's trainer and a search (docs/architecture.md, "Adding a
// regressor"): ssa-svr is the svr trainer searched by ssa, and `--method svr --search ssa` says the
// same. The names a method answers to come from the trainers (trainers.hpp), each of which lists
// its own; this file holds the pair and its names, and knows no trainer itself.
#pragma once

#include <compare>
#include <string>
#include <string_view>

namespace fogdrift {

/// How a regressor's hyperparameters are searched (train --search).
enum class Search {
  own,   ///< the trainer's own: ssa for gp's cv fit, none for svr, bp and poly
  none,  ///< none: svr with LIBSVM's defaults; bp, poly and gp's likelihood fit their own way
  ssa,   ///< sparrow search over the grouped folds (opt/ssa.hpp)
  pso,   ///< particle swarm
  gwo,   ///< grey wolf
};
/// "auto", "none", "ssa", "pso", "gwo".
std::string_view to_string(Search search);
Search parse_search(std::string_view text, std::string_view option = "search");
/// "auto, none, ssa, pso, gwo".
std::string search_names();
/// Whether the search runs an optimizer (ssa, pso, gwo).
bool is_optimizer(Search search);

/// A method name and the search it implies ("pso-svr": pso), as a trainer lists them.
struct MethodName {
  std::string_view name;
  Search search = Search::own;
  std::string_view doc;  ///< what the method is, for --method's help
};

struct Method {
  std::string_view trainer;  ///< a registered trainer's name: "svr", "bp", "poly", "gp"
  Search search = Search::own;

  friend bool operator==(const Method&, const Method&) = default;
  friend auto operator<=>(const Method&, const Method&) = default;  ///< for maps

  /// The paper's methods (Table 2) and the classical baseline, which code names.
  static const Method ssa_svr, pso_svr, gwo_svr, svr, bp, poly;
};
inline constexpr Method Method::ssa_svr{"svr", Search::ssa};
inline constexpr Method Method::pso_svr{"svr", Search::pso};
inline constexpr Method Method::gwo_svr{"svr", Search::gwo};
inline constexpr Method Method::svr{"svr", Search::own};
inline constexpr Method Method::bp{"bp", Search::own};
inline constexpr Method Method::poly{"poly", Search::own};

/// The method's name: its trainer's name for its search ("ssa-svr"), else the trainer's own
/// ("gp" searched by pso is "gp"; its model file says the search apart).
std::string to_string(const Method& method);
/// The method a name stands for; OptionError(option, "'rf' is not a method (…)") otherwise.
Method parse_method(std::string_view text, std::string_view option = "method");
/// Every registered name, "ssa-svr, pso-svr, gwo-svr, svr, bp, poly, gp".
std::string method_names();
/// `--method`'s help: each name and what it is, from the trainers.
std::string method_docs();

}  // namespace fogdrift
