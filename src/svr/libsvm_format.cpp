#include "fogdrift/svr/libsvm_format.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <string_view>

#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"

namespace fogdrift::svr {
namespace {

// Sparse rows of a file, all in one array: row r is entries[start[r], start[r + 1]). One array
// instead of a vector per row: reading 6000 rows took a malloc and a fresh page or two per row.
struct SparseRows {
  std::vector<std::size_t> start{0};
  std::vector<std::pair<std::size_t, double>> entries;
  std::size_t size() const { return start.size() - 1; }
};

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// fogdrift holds features densely (rows × features doubles), so a sparse file with a huge index
// would ask for more memory than any machine has. These limits make it an error first.
constexpr std::size_t kMaxFeatures = 100000;
constexpr std::size_t kMaxValues = std::size_t{1} << 27;  // 1 GiB of doubles

// Walks one line token by token, remembering the column for error messages.
class LineReader {
 public:
  LineReader(std::string_view line, const std::string& source, std::size_t line_no)
      : line_(line), source_(source), line_no_(line_no) {}

  bool at_end() {
    while (pos_ < line_.size() && is_blank(line_[pos_])) ++pos_;
    return pos_ >= line_.size();
  }
  std::size_t column() const { return pos_ + 1; }
  std::string_view token() {
    at_end();
    const std::size_t start = pos_;
    while (pos_ < line_.size() && !is_blank(line_[pos_])) ++pos_;
    token_column_ = start + 1;
    return line_.substr(start, pos_ - start);
  }
  [[noreturn]] void fail(const std::string& rule) const {
    throw InputError(source_, line_no_, token_column_, rule);
  }
  double number(std::string_view text, const char* what) const {
    double v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty())
      fail(fmt::format("{} '{}' is not a number", what, csv::excerpt(text)));
    if (!std::isfinite(v)) fail(fmt::format("{} '{}' is not finite", what, csv::excerpt(text)));
    return v;
  }
  // "INDEX:VALUE" with INDEX > previous.
  std::pair<std::size_t, double> feature(std::string_view tok, std::size_t previous) {
    const auto colon = tok.find(':');
    if (colon == std::string_view::npos)
      fail(fmt::format("'{}' is not INDEX:VALUE", csv::excerpt(tok)));
    std::size_t index = 0;
    const auto idx = tok.substr(0, colon);
    const auto [end, ec] = std::from_chars(idx.data(), idx.data() + idx.size(), index);
    if (ec != std::errc() || end != idx.data() + idx.size() || idx.empty() || index == 0)
      fail(fmt::format("feature index '{}' is not a positive integer", csv::excerpt(idx)));
    if (index > kMaxFeatures)
      fail(
          fmt::format("feature index {} is above the {} features fogdrift reads (it holds "
                      "features densely)",
                      index, kMaxFeatures));
    if (index <= previous)
      fail(
          fmt::format("feature index {} is not above the previous index {} (indices must "
                      "increase)",
                      index, previous));
    return {index, number(tok.substr(colon + 1), "feature value")};
  }
  // The rest of the line as INDEX:VALUE pairs, appended to `rows` as its next row; raises
  // `dims` to the largest index.
  void features(SparseRows& rows, std::size_t& dims) {
    std::size_t previous = 0;
    while (!at_end()) {
      rows.entries.push_back(feature(token(), previous));
      previous = rows.entries.back().first;
    }
    rows.start.push_back(rows.entries.size());
    dims = std::max(dims, previous);
  }

 private:
  std::string_view line_;
  const std::string& source_;
  std::size_t line_no_;
  std::size_t pos_ = 0;
  std::size_t token_column_ = 1;
};

// Splits text into lines (LF or CRLF); the last line may lack its newline.
template <typename F>
void for_each_line(const std::string& text, F&& f) {
  std::size_t start = 0, line_no = 1;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    f(std::string_view(text).substr(start, end - start), line_no);
    start = end + 1;
    ++line_no;
  }
}

// Densifies rows of (index, value) into a row-major matrix of `dims` columns; an InputError naming
// `source` when that is more than kMaxValues.
std::vector<double> densify(const SparseRows& rows, std::size_t dims, const std::string& source) {
  if (dims > 0 && rows.size() > kMaxValues / dims)
    throw InputError(source, 0, 0,
                     fmt::format("{} rows × {} features is more than the {} values (1 GiB) "
                                 "fogdrift holds in memory",
                                 rows.size(), dims, kMaxValues));
  std::vector<double> x(rows.size() * dims, 0.0);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t e = rows.start[i]; e < rows.start[i + 1]; ++e)
      x[i * dims + rows.entries[e].first - 1] = rows.entries[e].second;
  return x;
}

std::string sparse_line(double lead, const double* row, std::size_t dims) {
  std::string line = csv::format_number(lead);
  for (std::size_t k = 0; k < dims; ++k) {
    if (row[k] == 0) continue;
    line += fmt::format(" {}:{}", k + 1, csv::format_number(row[k]));
  }
  line += '\n';
  return line;
}

}  // namespace

// Room for the rows of `text` (one a line) and their entries (one per colon), so that reading
// grows no array.
SparseRows reserved_for(const std::string& text) {
  SparseRows rows;
  const auto lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
  rows.start.reserve(lines + 1);
  rows.entries.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), ':')));
  return rows;
}

Data parse_libsvm_data(const std::string& text, const std::string& source, std::size_t min_dims) {
  SparseRows rows = reserved_for(text);
  Data data;
  data.y.reserve(rows.start.capacity());
  std::size_t dims = min_dims;
  for_each_line(text, [&](std::string_view line, std::size_t line_no) {
    LineReader r(line, source, line_no);
    if (r.at_end()) {
      throw InputError(source, line_no, 0,
                       "empty line (each line is TARGET INDEX:VALUE …; remove blank lines)");
    }
    data.y.push_back(r.number(r.token(), "target"));
    r.features(rows, dims);
  });
  if (rows.size() == 0) throw InputError(source, 0, 0, "no samples (the file is empty)");
  data.rows = rows.size();
  data.cols = dims;
  data.x = densify(rows, dims, source);
  return data;
}

Data read_libsvm_data(const std::filesystem::path& path, std::size_t min_dims) {
  return parse_libsvm_data(read_text_file(path), path.string(), min_dims);
}

std::string to_libsvm_data(const Data& data) {
  std::string out;
  for (std::size_t i = 0; i < data.rows; ++i) out += sparse_line(data.y[i], data.row(i), data.cols);
  return out;
}

void write_libsvm_data(const Data& data, const std::filesystem::path& path) {
  write_text_atomically(path, to_libsvm_data(data));
}

Model parse_libsvm_model(const std::string& text, const std::string& source) {
  Model m;
  bool in_sv = false, have_kernel = false, have_rho = false, have_type = false;
  bool have_gamma = false;
  long total_sv = -1;
  SparseRows rows;
  std::size_t dims = 0;
  std::size_t last_line = 0;
  for_each_line(text, [&](std::string_view line, std::size_t line_no) {
    last_line = line_no;
    LineReader r(line, source, line_no);
    if (r.at_end()) return;
    if (in_sv) {
      m.coef.push_back(r.number(r.token(), "coefficient"));
      r.features(rows, dims);
      return;
    }
    const std::string key(r.token());
    if (key == "SV") {
      in_sv = true;
      return;
    }
    if (key == "svm_type") {
      const auto v = r.token();
      if (v != "epsilon_svr" && v != "nu_svr")
        r.fail(fmt::format("svm_type '{}' is not a regression model (epsilon_svr or nu_svr)", v));
      have_type = true;
    } else if (key == "kernel_type") {
      const auto v = r.token();
      if (v == "rbf")
        m.kernel = Kernel::rbf_gamma(m.kernel.gamma);
      else if (v == "linear")
        m.kernel = Kernel::linear();
      else
        r.fail(fmt::format("kernel_type '{}' is not supported (rbf or linear)", v));
      have_kernel = true;
    } else if (key == "gamma") {
      m.kernel.gamma = r.number(r.token(), "gamma");
      have_gamma = true;
    } else if (key == "rho") {
      m.rho = r.number(r.token(), "rho");
      have_rho = true;
    } else if (key == "total_sv") {
      const double v = r.number(r.token(), "total_sv");
      if (!(v >= 0 && v <= 1e12 && v == std::floor(v)))
        r.fail("total_sv must be a whole number ≥ 0");
      total_sv = static_cast<long>(v);
    } else if (key == "nr_class") {
      if (r.number(r.token(), "nr_class") != 2) r.fail("nr_class must be 2 for regression");
    } else if (key == "degree" || key == "coef0") {
      r.number(r.token(), key.c_str());  // unused by rbf and linear kernels
    } else {
      r.fail(fmt::format("unknown keyword '{}' in the model header", key));
    }
    if (!r.at_end()) r.fail("unexpected text after the value");
  });
  auto missing = [&](const char* what) {
    throw InputError(source, 0, 0, fmt::format("model header lacks '{}'", what));
  };
  if (!have_type) missing("svm_type");
  if (!have_kernel) missing("kernel_type");
  if (m.kernel.type == KernelType::rbf && !have_gamma) missing("gamma");
  if (!have_rho) missing("rho");
  if (!in_sv) missing("SV");
  if (m.kernel.type == KernelType::rbf && !(m.kernel.gamma > 0))
    throw InputError(source, 0, 0, "gamma must be > 0");
  if (total_sv >= 0 && static_cast<std::size_t>(total_sv) != m.coef.size())
    throw InputError(
        source, last_line, 0,
        fmt::format("total_sv is {} but {} support vectors follow", total_sv, m.coef.size()));
  m.dims = dims;
  m.support_vectors = densify(rows, dims, source);
  return m;
}

Model read_libsvm_model(const std::filesystem::path& path) {
  return parse_libsvm_model(read_text_file(path), path.string());
}

std::string to_libsvm_model(const Model& m) {
  std::string out = "svm_type epsilon_svr\n";
  if (m.kernel.type == KernelType::rbf) {
    out += "kernel_type rbf\n";
    out += "gamma " + csv::format_number(m.kernel.gamma) + "\n";
  } else {
    out += "kernel_type linear\n";
  }
  out += "nr_class 2\n";
  out += fmt::format("total_sv {}\n", m.size());
  out += "rho " + csv::format_number(m.rho) + "\n";
  out += "SV\n";
  for (std::size_t i = 0; i < m.size(); ++i)
    out += sparse_line(m.coef[i], m.support_vectors.data() + i * m.dims, m.dims);
  return out;
}

void write_libsvm_model(const Model& model, const std::filesystem::path& path) {
  write_text_atomically(path, to_libsvm_model(model));
}

Model read_any_model(const std::filesystem::path& path) {
  const std::string text = read_text_file(path);
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{') return model_from_json(text, path.string());
  return parse_libsvm_model(text, path.string());
}

}  // namespace fogdrift::svr
