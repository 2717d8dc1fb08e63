// LIBSVM's text formats, so that fogdrift reads what LIBSVM users already have and writes what
// their tools (svm-train, svm-predict, svm-scale, scikit-learn's load_svmlight_file) read.
//
// Data: one sample a line, "TARGET INDEX:VALUE INDEX:VALUE …", indices 1-based and strictly
// increasing, absent indices are zero. Model: LIBSVM's header ("svm_type epsilon_svr",
// "kernel_type rbf", "gamma …", "nr_class 2", "total_sv …", "rho …", "SV") and one
// "COEF INDEX:VALUE …" line per support vector. fogdrift writes every number with the shortest
// text that reads back to the same double (LIBSVM writes support vectors with 8 digits), so a
// model survives a round trip exactly and svm-predict reads it unchanged.
#pragma once

#include <filesystem>
#include <string>

#include "fogdrift/svr/kernel.hpp"
#include "fogdrift/svr/svr.hpp"

namespace fogdrift::svr {

/// Parses LIBSVM data. The number of features is the largest index seen, or `min_dims` when
/// larger. Errors (InputError with file, line and column): a malformed number, NaN or Inf, an
/// index that is not a positive integer or not above the previous one, an empty line, an empty
/// file.
Data parse_libsvm_data(const std::string& text, const std::string& source,
                       std::size_t min_dims = 0);
Data read_libsvm_data(const std::filesystem::path& path, std::size_t min_dims = 0);
/// Zero features are left out, as LIBSVM's tools do. Written atomically.
std::string to_libsvm_data(const Data& data);
void write_libsvm_data(const Data& data, const std::filesystem::path& path);

/// A model in LIBSVM's model-file format (ε-SVR; ν-SVR models are read too, their prediction is
/// the same). Rejects other SVM types and kernels with an InputError naming the line.
Model parse_libsvm_model(const std::string& text, const std::string& source);
Model read_libsvm_model(const std::filesystem::path& path);
std::string to_libsvm_model(const Model& model);
void write_libsvm_model(const Model& model, const std::filesystem::path& path);

/// Reads a model in either format: fogdrift's JSON (first non-blank character '{') or LIBSVM's.
Model read_any_model(const std::filesystem::path& path);

}  // namespace fogdrift::svr
