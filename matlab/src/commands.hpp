// The commands of fogdrift_mex (docs/matlab.md): each reads its arguments and appends its
// results; warnings go to `warnings` and the package's .m function raises them in the caller.
#pragma once

#include <string>
#include <vector>

#include "mx_convert.hpp"

namespace fogdrift::matlab {

struct Results {
  std::vector<MxPtr> values;          ///< the function's outputs, in order
  std::vector<std::string> warnings;  ///< said with warning() by the .m function
};

using Command = void (*)(const Args& args, Results& out);

struct NamedCommand {
  const char* name;      ///< fogdrift_mex's first argument
  const char* function;  ///< the package function users call, for messages
  Command run;
};

// svm_commands.cpp: LIBSVM's MATLAB convention.
void svmtrain(const Args& args, Results& out);
void svmpredict(const Args& args, Results& out);
void libsvmread(const Args& args, Results& out);

// drift_commands.cpp: the drift workflow.
void simulate(const Args& args, Results& out);
void train(const Args& args, Results& out);
void evaluate(const Args& args, Results& out);
void denoise(const Args& args, Results& out);
void options(const Args& args, Results& out);

// model_commands.cpp: fogdrift.Model's methods on a model's text.
void model_load(const Args& args, Results& out);
void model_info(const Args& args, Results& out);
void model_predict(const Args& args, Results& out);
void model_save(const Args& args, Results& out);
void model_export_c(const Args& args, Results& out);
void compensate(const Args& args, Results& out);
void read_recording(const Args& args, Results& out);

}  // namespace fogdrift::matlab
