#include "fogdrift/io/recording.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/io/campaign.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

namespace fs = std::filesystem;

Recording example(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  Recording r;
  for (std::size_t i = 0; i < n; ++i) {
    r.time_s.push_back(0.5 * static_cast<double>(i + 1));
    r.gyro_dph.push_back(13.0 + 0.03 * rng.normal());
    r.temp_fog_degc.push_back(-40.0 + 0.01 * static_cast<double>(i));
    r.temp_acc1_degc.push_back(rng.uniform(-40, 60));
    r.temp_acc2_degc.push_back(rng.normal() * 1e-7);
  }
  r.table_deg = std::vector<double>(n, 90.0);
  r.extra.push_back({"note, with comma", std::vector<std::string>(n, "say \"ok\"")});
  r.extra.push_back({"status", std::vector<std::string>(n, "")});
  return r;
}

TEST(Recording, RoundTripIsExact) {
  test::TempDir dir;
  const Recording original = example(500, 3);
  write_recording(dir / "r.csv", original);
  const Recording back = read_recording(dir / "r.csv");
  EXPECT_EQ(back.time_s, original.time_s);
  EXPECT_EQ(back.gyro_dph, original.gyro_dph);
  EXPECT_EQ(back.temp_fog_degc, original.temp_fog_degc);
  EXPECT_EQ(back.temp_acc1_degc, original.temp_acc1_degc);
  EXPECT_EQ(back.temp_acc2_degc, original.temp_acc2_degc);
  EXPECT_EQ(back.table_deg, original.table_deg);
  EXPECT_FALSE(back.accel_x_g.has_value());
  ASSERT_EQ(back.extra.size(), 2u);
  EXPECT_EQ(back.extra[0].name, "note, with comma");
  EXPECT_EQ(back.extra[0].cells, original.extra[0].cells);
  EXPECT_EQ(back.extra[1].cells, original.extra[1].cells);
  // Writing what was read gives the same bytes.
  EXPECT_EQ(to_csv(back), test::read_file(dir / "r.csv"));
}

TEST(Recording, ColumnsInAnyOrderAndExtrasKept) {
  test::TempDir dir;
  test::write_file(dir / "r.csv",
                   "logger_id,temp_acc2_degc,time_s,temp_acc1_degc,gyro_dph,temp_fog_degc\n"
                   "A7,1,0.5,2,3,4\nA7,1,1.5,2,3.5,4\n");
  const Recording r = read_recording(dir / "r.csv");
  EXPECT_EQ(r.gyro_dph, (std::vector<double>{3, 3.5}));
  ASSERT_EQ(r.extra.size(), 1u);
  EXPECT_EQ(r.extra[0].name, "logger_id");
  EXPECT_TRUE(r.has_column("logger_id"));
  EXPECT_THROW(r.numeric_column("logger_id"), InputError);
  EXPECT_THROW(r.numeric_column("absent"), std::out_of_range);
}

// A reader that holds only the extra columns asked for: the known ones always, the rest left in
// the file, still checked as CSV (a short row is an error whichever columns are held).
TEST(Recording, OnlyTheExtraColumnsAskedForAreHeld) {
  test::TempDir dir;
  const std::string header = "logger_id,time_s,gyro_dph,temp_fog_degc,gyro_y_dph,drift_true_dph\n";
  test::write_file(dir / "all.csv", header + "A7,0.5,3,4,1.25,0.1\nA7,1.5,3.5,4,1.5,0.2\n");
  const Recording all =
      read_recording(dir / "all.csv", {"gyro_y_dph", "logger_id", "drift_true_dph", "absent"});
  EXPECT_EQ(all.extra.size(), 3u);
  test::write_file(dir / "r.csv", header + "A7,0.5,3,4,1.25,x\nA7,1.5,3.5,4,1.5,y\n");
  EXPECT_THROW(read_recording(dir / "r.csv"), InputError);  // the true drift is numbers
  const Recording r = read_recording(dir / "r.csv", {"gyro_y_dph"});
  EXPECT_EQ(r.gyro_dph, (std::vector<double>{3, 3.5}));
  EXPECT_EQ(r.time_s, all.time_s);
  ASSERT_EQ(r.extra.size(), 1u);
  EXPECT_EQ(r.numeric_column("gyro_y_dph"), (std::vector<double>{1.25, 1.5}));
  EXPECT_FALSE(r.has_column("logger_id"));
  EXPECT_FALSE(r.has_column("drift_true_dph"));  // not held, so not checked as numbers
  test::write_file(dir / "short.csv",
                   "logger_id,time_s,gyro_dph,temp_fog_degc\nA7,0.5,3,4\nA7,1.5,3.5\n");
  EXPECT_THROW(read_recording(dir / "short.csv", {}), InputError);
}

TEST(Recording, ValidateRejectsInconsistentMemoryRecordings) {
  Recording r = example(10, 1);
  r.gyro_dph.pop_back();
  EXPECT_THROW(validate(r), InputError);
  r = example(10, 1);
  r.time_s[5] = r.time_s[4];
  EXPECT_THROW(validate(r), InputError);
  r = example(10, 1);
  r.temp_fog_degc[2] = std::nan("");
  EXPECT_THROW(validate(r), InputError);
}

// Every malformed input in tests/data/malformed fails with the message EXPECTED.tsv gives.
struct MalformedCase {
  std::string name;
  std::string expected;
};

std::vector<MalformedCase> malformed_cases() {
  std::ifstream in(test::data_path("malformed/EXPECTED.tsv"));
  std::vector<MalformedCase> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    cases.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return cases;
}

TEST(MalformedCorpus, EachInputFailsWithItsMessage) {
  const auto cases = malformed_cases();
  ASSERT_GE(cases.size(), 20u);
  for (const auto& c : cases) {
    const fs::path path = test::data_path("malformed/" + c.name);
    std::string message;
    try {
      if (fs::is_directory(path)) {
        const Campaign campaign = read_campaign(path);
        for (const auto& e : campaign.recordings) read_recording(campaign.path_of(e));
      } else {
        read_recording(path);
      }
    } catch (const InputError& e) {
      message = e.what();
    }
    ASSERT_FALSE(message.empty()) << c.name << " was accepted";
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << c.name << "\n  got:      " << message << "\n  expected: " << c.expected;
  }
}

}  // namespace
}  // namespace fogdrift
