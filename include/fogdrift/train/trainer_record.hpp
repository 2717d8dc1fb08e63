// A trainer's own part of a training summary (TrainSummary::record, docs/architecture.md "A
// regressor in its own room"): a value of a type the trainer declares in its own header, held
// by type and serialised by its own `to_json`, so that no central header lists what each trainer
// records and no trainer writes untyped JSON into the summary.
//
//   struct BpRecord { MlpSummary fit; };                     // bp_trainer.hpp
//   nlohmann::ordered_json to_json(const BpRecord& r);         // {"bp": {...}}
//   summary.record = TrainerRecord(BpRecord{fit.summary});     // bp_trainer.cpp
//   if (const BpRecord* r = summary.record.get<BpRecord>()) …  // typed, for a caller that knows
//   summary.record.json()                                      // its keys, for everyone else
#pragma once

#include <nlohmann/json.hpp>

#include <memory>
#include <utility>

namespace fogdrift {

/// A record type: `to_json(r)` (found by argument-dependent lookup) gives its keys in `fogdrift
/// train --json`, which summary_json puts beside the summary's own.
template <class R>
concept Record = requires(const R& r) {
  { to_json(r) } -> std::same_as<nlohmann::ordered_json>;
};

class TrainerRecord {
 public:
  /// Empty: the trainer recorded nothing (an SVR fitted without a search).
  TrainerRecord() = default;
  template <Record R>
  explicit TrainerRecord(R record) : held_(std::make_shared<const Held<R>>(std::move(record))) {}

  bool empty() const { return held_ == nullptr; }
  /// The record, if it is an R; nullptr otherwise.
  template <Record R>
  const R* get() const {
    const auto* held = dynamic_cast<const Held<R>*>(held_.get());
    return held ? &held->value : nullptr;
  }
  /// Its keys (to_json of the record); an empty object for an empty record.
  nlohmann::ordered_json json() const {
    return held_ ? held_->json() : nlohmann::ordered_json::object();
  }

 private:
  struct Base {
    virtual ~Base() = default;
    virtual nlohmann::ordered_json json() const = 0;
  };
  template <class R>
  struct Held final : Base {
    explicit Held(R r) : value(std::move(r)) {}
    nlohmann::ordered_json json() const override { return to_json(value); }
    R value;
  };
  std::shared_ptr<const Base> held_;
};

}  // namespace fogdrift
