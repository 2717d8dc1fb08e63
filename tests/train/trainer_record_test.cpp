// TrainerRecord (trainer_record.hpp): a trainer's part of the summary, held by its type and
// serialised by its own to_json.
#include "fogdrift/train/trainer_record.hpp"

#include <gtest/gtest.h>

#include <string>

namespace fogdrift {
namespace {

struct CountRecord {
  int count = 0;
};
nlohmann::ordered_json to_json(const CountRecord& r) {
  nlohmann::ordered_json j;
  j["count"] = r.count;
  return j;
}

struct NameRecord {
  std::string name;
};
nlohmann::ordered_json to_json(const NameRecord& r) {
  nlohmann::ordered_json j;
  j["name"] = r.name;
  return j;
}

TEST(TrainerRecord, EmptyHasNoKeysAndNoType) {
  const TrainerRecord r;
  EXPECT_TRUE(r.empty());
  EXPECT_EQ(r.json(), nlohmann::ordered_json::object());
  EXPECT_EQ(r.get<CountRecord>(), nullptr);
}

TEST(TrainerRecord, GivesBackItsOwnTypeOnly) {
  const TrainerRecord r(CountRecord{7});
  EXPECT_FALSE(r.empty());
  ASSERT_NE(r.get<CountRecord>(), nullptr);
  EXPECT_EQ(r.get<CountRecord>()->count, 7);
  EXPECT_EQ(r.get<NameRecord>(), nullptr);  // another trainer's record is not this one
}

TEST(TrainerRecord, SerialisesByItsOwnToJson) {
  EXPECT_EQ(TrainerRecord(NameRecord{"gp"}).json().dump(), R"({"name":"gp"})");
  // A copy shares the value: a summary is copied freely.
  const TrainerRecord a(CountRecord{3});
  const TrainerRecord b = a;
  EXPECT_EQ(b.get<CountRecord>(), a.get<CountRecord>());
}

}  // namespace
}  // namespace fogdrift
