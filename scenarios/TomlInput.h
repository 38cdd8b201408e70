#pragma once
// TOML text parsed for the scenario-layer readers (scenarios, car files, studies), with
// one form of syntax error: "<source>:<line>:<column>: TOML syntax error: <what>".
#include <string>
#include <string_view>
#include <toml++/toml.h>

namespace rockroll {

/// ScenarioError (scenarios/ScenarioLoader.h) for text that is not TOML.
toml::table parseToml(std::string_view text, const std::string& source);

}  // namespace rockroll
