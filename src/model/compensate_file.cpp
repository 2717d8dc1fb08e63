// A recording file compensated (compensate_file.hpp; docs/compensation.md).
#include "fogdrift/model/compensate_file.hpp"

#include <fmt/format.h>

#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/csv_rows.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"
#include "fogdrift/io/recording.hpp"
#include "fogdrift/io/target.hpp"

namespace fogdrift {

std::vector<std::string> compensated_columns(const std::string& target) {
  if (target == "gyro_dph") return {"drift_dph", "gyro_comp_dph", "novelty", "guard_weight"};
  const Target t = target_of(target);
  return {t.drift_column(), t.compensated_column(), "novelty_" + t.axis, "guard_weight_" + t.axis};
}

std::vector<CompensatedAxis> compensate_file(const ModelSet& set,
                                             const std::filesystem::path& input,
                                             const std::filesystem::path& output,
                                             const CompensateOptions& options) {
  const std::string source = input.string();
  // Only the columns a model reads are held; the others are copied from the file as they are.
  std::vector<std::string> needed;
  for (const CompensationModel& model : set.models) {
    needed.push_back(model.dataset.target_column);
    for (const std::string& c : model.dataset.features.thermometer_columns()) needed.push_back(c);
  }
  const Recording recording = read_recording(input, needed);
  // The input again, row by row, to copy each row's fields as they are beside the new columns
  // (csv_rows.hpp: no second copy of the file in memory).
  std::ifstream in = open_text_file(input);
  csv::RowReader table(in, source);
  std::vector<CompensatedAxis> axes;
  for (const CompensationModel& model : set.models) {
    CompensatedAxis x;
    x.model = &model;
    x.columns = compensated_columns(model.dataset.target_column);
    for (const std::string& name : x.columns)
      if (table.find(name))
        throw InputError(
            table.file(), 1, *table.find(name) + 1,
            fmt::format("already has a {} column; compensate the original recording", name));
    x.reading = target_values(recording, model.dataset.target_column);
    x.prediction = model.predict(recording, options.guarded);
    x.novelty = summarize_novelty(x.prediction.novelty, x.prediction.weight);
    axes.push_back(std::move(x));
  }

  write_file_atomically(output, [&](std::ostream& out) {
    std::string line;
    auto add_field = [&line](std::string_view f) {
      csv::append_quoted(line, f);
      line += ',';
    };
    for (const std::string& f : table.header()) add_field(f);
    for (const CompensatedAxis& x : axes)
      for (const std::string& f : x.columns) add_field(f);
    line.back() = '\n';
    out << line;
    std::vector<std::string_view> fields;
    std::size_t line_no = 0;
    const std::size_t rows = recording.size();
    std::size_t i = 0;
    const bool comma_separated = table.delimiter() == ',';
    for (; table.next(fields, line_no); ++i) {
      if (i == rows)
        throw InputError(source, line_no, 0, "changed while it was read; compensate it again");
      line.clear();
      // A comma-separated row without a quote or a space is its fields as add_field copies them:
      // none needs quotes. Copied whole, a kilohertz log's row is one append, not ten.
      const std::string_view text = table.row_text();
      if (comma_separated && text.find('"') == std::string_view::npos &&
          text.find(' ') == std::string_view::npos) {
        line += text;
        line += ',';
      } else {
        for (std::string_view f : fields) add_field(f);
      }
      for (const CompensatedAxis& x : axes) {
        const double drift = x.prediction.drift_dph[i];
        for (double v :
             {drift, x.reading[i] - drift, x.prediction.novelty[i], x.prediction.weight[i]}) {
          csv::append_number(line, v);
          line += ',';
        }
      }
      line.back() = '\n';
      out << line;
    }
    if (i != rows) throw InputError(source, 0, 0, "changed while it was read; compensate it again");
  });
  return axes;
}

}  // namespace fogdrift
