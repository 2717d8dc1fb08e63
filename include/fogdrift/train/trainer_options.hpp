// Each trainer's own options, kept in TrainOptions by their type (trainer.hpp: T::Options), so
// that TrainOptions names no trainer's options and a new trainer adds none to it. A trainer reads
// its own, `options.trainers.get<PolyOptions>()`; one never set reads as its type's defaults.
#pragma once

#include <map>
#include <memory>
#include <typeindex>
#include <utility>

namespace fogdrift {

class TrainerOptions {
 public:
  TrainerOptions() = default;
  TrainerOptions(const TrainerOptions& other) { *this = other; }
  TrainerOptions& operator=(const TrainerOptions& other) {
    if (this == &other) return *this;
    held_.clear();
    for (const auto& [type, held] : other.held_) held_.emplace(type, held->clone());
    return *this;
  }
  TrainerOptions(TrainerOptions&&) noexcept = default;
  TrainerOptions& operator=(TrainerOptions&&) noexcept = default;
  ~TrainerOptions() = default;

  /// The options of type O, to set: made with O's defaults the first time.
  template <class O>
  O& get() {
    auto [it, fresh] = held_.try_emplace(std::type_index(typeid(O)));
    if (fresh) it->second = std::make_unique<Held<O>>();
    return static_cast<Held<O>&>(*it->second).value;
  }
  /// The options of type O as set, or O's defaults.
  template <class O>
  const O& get() const {
    static const O kDefaults{};
    const auto it = held_.find(std::type_index(typeid(O)));
    return it == held_.end() ? kDefaults : static_cast<const Held<O>&>(*it->second).value;
  }

 private:
  struct Base {
    virtual ~Base() = default;
    virtual std::unique_ptr<Base> clone() const = 0;
  };
  template <class O>
  struct Held final : Base {
    O value{};
    std::unique_ptr<Base> clone() const override { return std::make_unique<Held>(*this); }
  };
  std::map<std::type_index, std::unique_ptr<Base>> held_;
};

}  // namespace fogdrift
