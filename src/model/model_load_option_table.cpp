// How a model file is loaded (model_load_option_table.hpp). Defaults are ModelLoadOptions'.
#include "fogdrift/model/model_load_option_table.hpp"

namespace fogdrift {
namespace {

OptionTable<ModelLoadOptions> make_model_load_table() {
  using O = ModelLoadOptions;
  OptionTable<O> t;
  t.push_back(on_off_option<O>(
      {"allow_edited",
       "--allow-edited",
       {},
       "",
       "",
       "Load a model file whose content no longer matches its checksum (an edit made on "
       "purpose); its fields are still checked",
       {}},
      [](auto& o) -> auto& { return o.allow_edited; }));
  t.push_back(on_off_option<O>(
      {"allow_old_format",
       "--allow-old-format",
       {},
       "",
       "",
       "Load a model file of format version 1 or 2, written before model files carried a "
       "checksum (version 1 also has no novelty guard and compensates unguarded)",
       {}},
      [](auto& o) -> auto& { return o.allow_old_format; }));
  return t;
}

}  // namespace

const OptionTable<ModelLoadOptions>& model_load_option_table() {
  static const OptionTable<ModelLoadOptions> table = make_model_load_table();
  return table;
}

}  // namespace fogdrift
