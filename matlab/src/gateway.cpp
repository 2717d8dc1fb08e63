// fogdrift_mex: the one MEX file behind the +fogdrift package (docs/matlab.md). Called as
//   [err, warnings, out1, out2, …] = fogdrift_mex(COMMAND, args…)
// it runs the command and never raises: err is [] or struct('identifier', …, 'message', …) and
// the package's .m function raises it with error(), so messages read in the function's name and
// no C++ object is alive when the host unwinds. Ctrl-C in Octave reaches the library's interrupt
// (interrupt.hpp) while a command runs.
#include <mex.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <new>
#include <string>
#include <thread>

#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/interrupt.hpp"
#include "fogdrift/base/memory.hpp"

#ifdef HAVE_OCTAVE
#include <octave/quit.h>
#endif

namespace fogdrift::matlab {
namespace {

constexpr NamedCommand kCommands[] = {
    {"svmtrain", "fogdrift.svmtrain", svmtrain},
    {"svmpredict", "fogdrift.svmpredict", svmpredict},
    {"libsvmread", "fogdrift.libsvmread", libsvmread},
    {"simulate", "fogdrift.simulate", simulate},
    {"train", "fogdrift.train", train},
    {"evaluate", "fogdrift.evaluate", evaluate},
    {"denoise", "fogdrift.denoise", denoise},
    {"options", "fogdrift.options", options},
    {"read_recording", "fogdrift.read_recording", read_recording},
    {"model_load", "fogdrift.Model.load", model_load},
    {"model_info", "fogdrift.Model", model_info},
    {"model_predict", "fogdrift.Model.predict", model_predict},
    {"model_save", "fogdrift.Model.save", model_save},
    {"model_export_c", "fogdrift.Model.exportC", model_export_c},
    {"compensate", "fogdrift.compensate", compensate},
};

/// Polls the host's interrupt flag while a command runs and passes it to the library.
class InterruptWatch {
 public:
  InterruptWatch() {
    clear_interrupt();
#ifdef HAVE_OCTAVE
    thread_ = std::thread([this] {
      while (!done_.load()) {
        if (octave_interrupt_state > 0) request_interrupt();
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    });
#endif
  }
  ~InterruptWatch() {
    done_.store(true);
    if (thread_.joinable()) thread_.join();
    clear_interrupt();
  }

 private:
  std::atomic<bool> done_{false};
  std::thread thread_;
};

MxPtr error_struct(const char* identifier, const std::string& message) {
  const char* names[] = {"identifier", "message"};
  MxPtr e(mxCreateStructMatrix(1, 1, 2, names));
  mxSetField(e.get(), 0, "identifier", mxCreateString(identifier));
  mxSetField(e.get(), 0, "message", mxCreateString(message.c_str()));
  return e;
}

/// Runs the command; the error, if any, as a struct.
MxPtr run(const NamedCommand& c, const Args& args, Results& out) {
  try {
    InterruptWatch watch;
    c.run(args, out);
    return nullptr;
  } catch (const OptionError& e) {
    return error_struct("fogdrift:badOption", std::string(c.function) + ": " + e.what());
  } catch (const InputError& e) {
    return error_struct("fogdrift:badInput", std::string(c.function) + ": " + e.what());
  } catch (const Interrupted&) {
    return error_struct("fogdrift:interrupted",
                        std::string(c.function) + ": interrupted (Ctrl-C); nothing was written");
  } catch (const ResourceError& e) {
    return error_struct("fogdrift:outOfMemory", std::string(c.function) + ": " + e.what());
  } catch (const std::bad_alloc&) {
    return error_struct("fogdrift:outOfMemory",
                        std::string(c.function) + ": out of memory; give it fewer rows");
  } catch (const std::exception& e) {
    return error_struct("fogdrift:internal", std::string(c.function) + ": " + e.what());
  }
}

}  // namespace
}  // namespace fogdrift::matlab

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  using namespace fogdrift::matlab;
  // Nothing here may raise before the results are handed over: the host's error would unwind
  // through C++ frames.
  MxPtr error;
  Results out;
  const NamedCommand* command = nullptr;
  if (nrhs >= 1 && mxIsChar(prhs[0])) {
    char name[64] = {0};
    mxGetString(prhs[0], name, sizeof name);
    for (const NamedCommand& c : kCommands)
      if (std::strcmp(c.name, name) == 0) command = &c;
  }
  if (!command) {
    error = error_struct("fogdrift:internal",
                         "fogdrift_mex: the first argument must name a command; call the "
                         "functions of the fogdrift package (help fogdrift) instead");
  } else {
    Args args{command->function, std::span<const mxArray* const>(prhs + 1, nrhs - 1)};
    error = run(*command, args, out);
  }
  if (error) out.values.clear();
  for (int k = 0; k < nlhs; ++k) {
    if (k == 0) {
      plhs[0] = error ? error.release() : mxCreateDoubleMatrix(0, 0, mxREAL);
    } else if (k == 1) {
      plhs[1] = mxCreateCellMatrix(out.warnings.size(), 1);
      for (std::size_t i = 0; i < out.warnings.size(); ++i)
        mxSetCell(plhs[1], i, mxCreateString(out.warnings[i].c_str()));
    } else {
      const std::size_t i = static_cast<std::size_t>(k - 2);
      plhs[k] =
          i < out.values.size() ? out.values[i].release() : mxCreateDoubleMatrix(0, 0, mxREAL);
    }
  }
}
