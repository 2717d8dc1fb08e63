// The files of a run (base/run_files.hpp): which paths name a descriptor the process has, and
// that the writers write through them and through links instead of replacing them. The rest
// (inputs refused as outputs, signals removing temporaries) needs the command line's guarded
// run and is tested on the command (tests/cli/attacks_test.sh).
#include "fogdrift/base/run_files.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(RunFiles, DescriptorsAreNamedByTheirPathsAndTheLinksToThem) {
  EXPECT_EQ(standard_descriptor_of("/dev/stdout"), 1);
  EXPECT_EQ(standard_descriptor_of("/dev/stderr"), 2);
  EXPECT_EQ(standard_descriptor_of("/dev/fd/7"), 7);
  EXPECT_EQ(standard_descriptor_of("/proc/self/fd/3"), 3);
  EXPECT_EQ(standard_descriptor_of("/dev/fd/x"), std::nullopt);
  EXPECT_EQ(standard_descriptor_of("/dev/null"), std::nullopt);
  EXPECT_EQ(standard_descriptor_of("model.h"), std::nullopt);
  const fs::path dir = fs::temp_directory_path() / ("run_files_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::create_symlink("/dev/stdout", dir / "out");
  EXPECT_EQ(standard_descriptor_of(dir / "out"), 1);
  fs::remove_all(dir);
}

TEST(RunFiles, ADescriptorIsWrittenThroughAndALinkStaysALink) {
  const fs::path dir = fs::temp_directory_path() / ("run_files_w" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // A descriptor opened for appending: the bytes go after what it holds.
  std::ofstream(dir / "shell.txt") << "kept\n";
  const int fd = ::open((dir / "shell.txt").c_str(), O_WRONLY | O_APPEND);
  ASSERT_GE(fd, 0);
  write_text_atomically("/dev/fd/" + std::to_string(fd), "written\n");
  ::close(fd);
  EXPECT_EQ(read_all(dir / "shell.txt"), "kept\nwritten\n");
  // A link: its target is replaced, the link is not.
  std::ofstream(dir / "target.txt") << "old";
  fs::create_symlink(dir / "target.txt", dir / "link.txt");
  write_text_atomically(dir / "link.txt", "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(read_all(dir / "target.txt"), "new");
  // A dangling link creates its target.
  fs::create_symlink("absent.txt", dir / "dangling.txt");
  write_text_atomically(dir / "dangling.txt", "made");
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.txt"));
  EXPECT_EQ(read_all(dir / "absent.txt"), "made");
  // A closed descriptor is an error, not a file that takes its number.
  EXPECT_THROW(write_text_atomically("/dev/fd/987", "x"), std::exception);
  fs::remove_all(dir);
}

// A host that notes no inputs names them: the same file through a link, or a folder that holds
// one, is refused naming the option; other outputs pass.
TEST(RunFiles, AnOutputAmongTheNamedInputsIsRefused) {
  const fs::path dir = fs::temp_directory_path() / "fogdrift_among_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "cal");
  std::ofstream(dir / "cal" / "unit.json") << "{}";
  fs::create_symlink(dir / "cal" / "unit.json", dir / "link.json");
  const std::vector<fs::path> inputs = {dir / "cal" / "unit.json"};
  auto message = [&](const fs::path& output) -> std::string {
    try {
      check_output_not_among(output, inputs, "out");
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), "out");
      return e.message();
    }
    return "";
  };
  EXPECT_NE(message(dir / "cal" / "unit.json").find("which this call reads"), std::string::npos);
  EXPECT_NE(message(dir / "link.json").find("which this call reads"), std::string::npos);
  EXPECT_NE(message(dir / "cal").find("holds"), std::string::npos);
  EXPECT_NE(message(dir / "cal" / ".." / "cal").find("holds"), std::string::npos);
  EXPECT_EQ(message(dir / "other"), "");
  EXPECT_EQ(message(dir / "cal" / "model.json"), "");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fogdrift
