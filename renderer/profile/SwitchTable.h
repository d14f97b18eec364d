#pragma once
// The one table of profile switches. Each row says everything about a switch: key, kind,
// allowed values or range, default, one line of documentation, how it reaches the shaders,
// and how to read/write it on a Profile. The loaders (`--set`, TOML profiles: ProfileLoader.h),
// `describe`, the JSON dumps and the shader variant defines all iterate this table.
#include "profile/Profile.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pb::profile {

enum class SwitchKind {
    Choice, // one of `choices`
    Number, // a finite number in [minValue, maxValue]
    Text,   // free text checked by `validate`
};

// How a switch reaches the shaders.
//   ChoiceFlag: `#define <define>_<VALUE>` (value upper-cased), e.g. GI_LOOPS_SPLIT
//   Value:      `#define <define> <value>` (numbers)
//   HostOnly:   no define; the pass acts on it (e.g. which volumes are uploaded)
enum class DefineStyle { ChoiceFlag, Value, HostOnly };

struct SwitchInfo {
    std::string key;
    SwitchKind kind = SwitchKind::Choice;
    std::vector<std::string> choices;  // Choice
    double minValue = 0, maxValue = 0; // Number
    std::string defaultValue;          // text form
    std::string doc;                   // one line
    DefineStyle defineStyle = DefineStyle::HostOnly;
    std::string define;
    // Text: "" when fine, else why not (one line, without the key).
    std::function<std::string(const std::string&)> validate;
    std::function<std::string(const Profile&)> get;
    std::function<void(Profile&, const std::string&)> set; // input already validated
};

const std::vector<SwitchInfo>& switchTable();
// nullptr when unknown.
const SwitchInfo* findSwitch(const std::string& key);

// Why `value` is not allowed for `info` ("" when it is): "allowed values: full, half, quarter".
std::string switchValueProblem(const SwitchInfo& info, const std::string& value);

// The #defines a profile gives the shaders (every ChoiceFlag/Value row), keyed like
// pb::gl::Defines (a plain std::map so this library stays GL-free).
std::map<std::string, std::string> shaderDefines(const Profile& p);

// Every switch: key, kind, values/range, default, current value, doc, define.
nlohmann::json describeSwitches(const Profile& current);
// Aligned text for terminals, one switch per paragraph.
std::string describeSwitchesText(const Profile& current);

} // namespace pb::profile
