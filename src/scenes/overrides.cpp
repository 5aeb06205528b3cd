#include "scenes/overrides.h"

#include <algorithm>
#include <cstdio>
#include <string_view>

#include "scenes/parameters.h"

namespace scenes {
namespace {

std::string_view trim(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
    return text;
}

}  // namespace

std::vector<std::string> splitOverrides(const std::vector<std::string>& lists) {
    std::vector<std::string> settings;
    for (const std::string& list : lists) {
        std::size_t start = 0;
        while (start <= list.size()) {
            const std::size_t comma = std::min(list.find(',', start), list.size());
            const std::string_view part = trim(std::string_view(list).substr(start, comma - start));
            if (!part.empty()) settings.emplace_back(part);
            start = comma + 1;
        }
    }
    return settings;
}

std::string checkOverrides(const Scene& scene, const std::vector<std::string>& overrides) {
    if (overrides.empty()) return "give at least one name=value to compare, e.g. method=velocity";
    Scene copy = scene;
    for (const std::string& setting : overrides) {
        if (const std::string error = applySetting(copy, setting); !error.empty()) {
            return setting + ": " + error;
        }
    }
    return settingsThatActOnNothing(copy, overrides);
}

namespace {

std::string shownValue(const Parameter& parameter, const Scene& scene, bool exact) {
    std::string value = formatValue(parameter, scene);
    if (exact || parameter.kind == ParameterKind::Choice || value.size() <= 9) return value;
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.6g", parameter.get(scene));
    return shorter;
}

}  // namespace

std::vector<ShownSetting> shownSettings(const Scene& scene, const std::vector<std::string>& overrides, bool exact) {
    std::vector<ShownSetting> shown;
    for (const std::string& setting : overrides) {
        const std::string name = settingName(setting);
        const Parameter* parameter = findParameter(name);
        const auto seen = [&](const ShownSetting& s) { return s.name == name; };
        if (!parameter || std::any_of(shown.begin(), shown.end(), seen)) continue;
        shown.push_back({name, shownValue(*parameter, scene, exact)});
    }
    return shown;
}

std::string overrideLabel(const std::vector<ShownSetting>& settings) {
    std::string label;
    for (const ShownSetting& s : settings) label += (label.empty() ? "" : ", ") + s.name + " = " + s.value;
    return label;
}

namespace {

bool hasName(std::string_view setting) { return setting.find('=') != std::string_view::npos; }

}  // namespace

std::string overrideVariants(const Scene& scene, const std::vector<std::string>& lists, Variants& variants) {
    // The settings as written, each name with its values (a value after a comma without a
    // name is another value of the name before it).
    std::vector<std::pair<std::string, std::vector<std::string>>> settings;
    for (const std::string& part : splitOverrides(lists)) {
        if (hasName(part)) {
            const std::string name = settingName(part), value(trim(std::string_view(part).substr(part.find('=') + 1)));
            const auto written = std::find_if(settings.begin(), settings.end(), [&](const auto& s) { return s.first == name; });
            if (written == settings.end()) {
                settings.push_back({name, {value}});
            } else {  // a name written again: one more of its values
                written->second.push_back(value);
                std::rotate(written, written + 1, settings.end());  // a bare value after it is its too
            }
            continue;
        }
        if (settings.empty()) {
            return findParameter(part) ? "'" + part + "' has no value: write " + part + "=value"
                                       : "'" + part + "' has no name: write name=value,value";
        }
        settings.back().second.push_back(part);
    }
    // A view per combination of the values: the names with several first (their values
    // label the views), then the others, each group in the order written. More than
    // kMostViews combinations cannot fit, even with the one A shows left out.
    std::stable_partition(settings.begin(), settings.end(), [](const auto& setting) { return setting.second.size() > 1; });
    std::size_t combinations = 1;
    for (const auto& [name, values] : settings) {
        if (int(values.size()) > kMostViews) {
            return "at most " + std::to_string(kMostViews) + " values of " + name + " (one view each)";
        }
        combinations *= values.size();
        if (combinations > std::size_t(kMostViews)) {
            return "at most " + std::to_string(kMostViews) + " views: A and " + std::to_string(kMostViews - 1) + " others";
        }
    }
    Variants all{{}};
    for (const auto& [name, values] : settings) {
        Variants combined;
        for (const std::vector<std::string>& variant : all) {
            for (const std::string& value : values) {
                combined.push_back(variant);
                combined.back().push_back(name + "=" + value);
            }
        }
        all = std::move(combined);
    }
    for (const std::vector<std::string>& variant : all) {
        if (const std::string error = checkOverrides(scene, variant); !error.empty()) return error;
    }
    // Views that show what A shows are left out, unless none differs.
    Variants differing;
    for (const std::vector<std::string>& variant : all) {
        if (!changesNothing(scene, {variant})) differing.push_back(variant);
    }
    if (!differing.empty()) all = std::move(differing);
    if (int(all.size()) > kMostViews - 1) {
        return "at most " + std::to_string(kMostViews) + " views: A and " + std::to_string(kMostViews - 1) + " others";
    }
    variants = std::move(all);
    return "";
}

bool changesNothing(const Scene& scene, const Variants& variants) {
    for (const std::vector<std::string>& variant : variants) {
        Scene copy = scene;
        for (const std::string& setting : variant) applySetting(copy, setting);
        if (overrideLabel(copy, variant, true) != overrideLabel(scene, variant, true)) return false;
    }
    return true;
}

std::string settingName(std::string_view setting) { return std::string(trim(setting.substr(0, setting.find('=')))); }

std::vector<std::string> slidersToMove(const Scene& scene) {
    std::vector<std::string> compared, claimed;
    for (const std::string& part : splitOverrides(scene.compare)) {
        if (part.find('=') != std::string::npos) compared.push_back(settingName(part));  // not a bare value
    }
    for (const Claim& claim : scene.claims) {
        if (claim.in != ClaimSource::Description) continue;
        for (const std::string& setting : claim.settings) claimed.push_back(settingName(setting));
    }
    const auto named = [](const std::vector<std::string>& names, std::string_view name) {
        return std::find(names.begin(), names.end(), name) != names.end();
    };
    std::vector<std::string> sliders;
    for (const Parameter& p : parameterTable()) {
        if (named(compared, p.name)) sliders.emplace_back(p.name);
    }
    for (const Parameter& p : parameterTable()) {
        if (named(claimed, p.name) && !named(compared, p.name)) sliders.emplace_back(p.name);
    }
    return sliders;
}

}  // namespace scenes
