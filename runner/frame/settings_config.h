// The one TechniqueConfig class every registry entry makes: a technique's
// settings struct and three hooks of its own (its override keys, setting one,
// making the technique), instead of a hand-written subclass per technique.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frame/technique.h"

namespace pn {

// `Settings` has a `std::string name` (as the user wrote it, overrides included) and a
// `validate() const` that throws Error naming the setting and its range.
template <class Settings>
struct SettingsHooks {
  std::vector<std::string> (*keys)();  // the override keys the technique owns
  // Throws Error naming the technique (settings.name), the key and what it expects.
  void (*set)(Settings& settings, const std::string& key, const std::string& value);
  std::unique_ptr<Technique> (*create)(TechniqueResources& resources, const Settings& settings);
  // The second layer the settings read (TechniqueConfig::second_layer); null: none.
  std::optional<MapLayer> (*second_layer)(const Settings& settings) = nullptr;
};

template <class Settings>
class SettingsConfig final : public TechniqueConfig {
 public:
  SettingsConfig(Settings settings, SettingsHooks<Settings> hooks) : settings_(std::move(settings)), hooks_(hooks) {}
  std::string name() const override { return settings_.name; }
  void rename(const std::string& name) override { settings_.name = name; }
  std::vector<std::string> keys() const override { return hooks_.keys(); }
  void set(const std::string& key, const std::string& value) override { hooks_.set(settings_, key, value); }
  void validate() const override { settings_.validate(); }
  std::unique_ptr<Technique> create(TechniqueResources& resources) const override {
    return hooks_.create(resources, settings_);
  }
  std::unique_ptr<TechniqueConfig> clone() const override { return std::make_unique<SettingsConfig>(*this); }
  std::optional<MapLayer> second_layer() const override {
    return hooks_.second_layer != nullptr ? hooks_.second_layer(settings_) : std::nullopt;
  }

 private:
  Settings settings_;
  SettingsHooks<Settings> hooks_;
};

template <class Settings>
std::unique_ptr<TechniqueConfig> settings_config(Settings settings, SettingsHooks<Settings> hooks) {
  return std::make_unique<SettingsConfig<Settings>>(std::move(settings), hooks);
}

}  // namespace pn
