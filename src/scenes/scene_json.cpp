#include "scenes/scene_json.h"

#include <algorithm>
#include <iterator>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>
#include <utility>

#include "platform/whole_file.h"
#include "scenes/generate.h"
#include "scenes/json_locate.h"
#include "scenes/overrides.h"
#include "scenes/parameters.h"
#include "scenes/suggest.h"

namespace scenes {

namespace {

using Json = nlohmann::json;
using Keys = std::vector<std::string_view>;

// The longest title (and slide) and description a scene may have, in bytes: the presets'
// longest are 45 and about 1 100.
constexpr std::size_t kLongestTitle = 200, kLongestDescription = 20000;
const Keys kSceneKeys = {"title", "slide",   "description", "box",      "planes", "parameters",
                         "seed",  "spheres", "generate",    "emitters", "time",   "steps",
                         "claims", "compare", "mirror", "camera", "time_scale", "paused", "color_by"};
const Keys kCameraKeys = {"azimuth", "elevation", "fits"};
const Keys kMirrorKeys = {"point", "normal"};
const Keys kBoxKeys = {"size", "tilt"};
const Keys kPlaneKeys = {"point", "normal", "thickness"};
const Keys kSphereKeys = {"p", "v", "r", "m"};
const Keys kGeneratorKeys = {"kind", "count",    "region",         "radius", "density",
                             "mass", "velocity", "velocitySpread", "seed"};
const Keys kEmitterKeys = {"period",  "position", "velocity", "spread", "radius",
                           "density", "mass",     "max",      "emitted"};
const Keys kRegionKeys = {"min", "max"};
const Keys kClaimKeys = {"says", "in",   "set", "measure", "sphere", "plane", "name", "from",
                         "to",   "take", "nth", "ratio_to", "near",  "within", "min", "max"};
const Keys kKinds = {"lattice", "random"};
constexpr double kMaxTilt = 90.0;                   // degrees
constexpr double kMostElevation = 88.0;             // degrees, as --camera takes it
constexpr double kMaxInteger = 9007199254740992.0;  // whole numbers beyond 2^53 are not exact
// The largest size (m), mass (kg), density, speed (m/s), coordinate (m) or time (s) a scene
// file may give, and 1 over it the smallest positive one: far beyond any scene, and the
// energies they make stay finite.
constexpr double kPhysical = 1e9;

// Control characters (a newline in a key) would break the one-line message.
std::string oneLine(std::string text) {
    for (char& c : text) {
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    }
    return text;
}

std::string typeName(const Json& v) {
    switch (v.type()) {
        case Json::value_t::object:
            return "an object";
        case Json::value_t::array:
            return "an array";
        case Json::value_t::string:
            return "a string";
        case Json::value_t::boolean:
            return "a boolean";
        case Json::value_t::null:
            return "null";
        default:
            return "a number";
    }
}

Keys parameterNames() {
    Keys names;
    for (const Parameter& p : parameterTable()) names.push_back(p.name);
    return names;
}

// Reads a parsed scene, checking every value, and reports each error at the
// line of the offending key or value.
class SceneReader {
  public:
    SceneReader(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    [[noreturn]] void failAt(std::size_t offset, const std::string& what) const {
        const detail::TextPosition at = detail::positionOf(text_, offset);
        throw SceneError(file_ + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                         ": " + oneLine(what));
    }
    [[noreturn]] void fail(const std::string& pointer, const std::string& what,
                           bool atKey = false) const {
        failAt(detail::offsetOf(text_, pointer, atKey), what);
    }

    // A text field, refused when longer than `most` characters (bytes): a panel shows it,
    // and a megabyte of one word took seconds a frame to lay out.
    std::string text(const Json& root, const char* key, std::size_t most) const {
        std::string value = string(root, "", key);
        if (value.size() > most) {
            fail(std::string("/") + key, std::string(key) + " is " + std::to_string(value.size()) + " characters long; at most " +
                                             std::to_string(most));
        }
        return value;
    }

    Scene read(const Json& root) {
        Scene scene;
        checkKeys(root, "", kSceneKeys);
        scene.title = text(root, "title", kLongestTitle);
        scene.slide = text(root, "slide", kLongestTitle);
        scene.description = text(root, "description", kLongestDescription);
        if (const Json* box = find(root, "box")) scene.box = readBox(*box, "/box");
        scene.planes = readList(root, "planes", &SceneReader::readPlane);
        scene.mirrors = readList(root, "mirror", &SceneReader::readMirror);
        if (const Json* camera = find(root, "camera")) scene.camera = readCamera(*camera, "/camera");
        if (const Json* scale = find(root, "time_scale")) {
            scene.timeScale = inRange(*scale, "/time_scale", kTimeScaleRange[0], kTimeScaleRange[1]);
        }
        if (const Json* paused = find(root, "paused")) scene.opensPaused = boolean(*paused, "/paused");
        if (find(root, "color_by")) scene.colorBy = readColorBy(string(root, "", "color_by"), "/color_by");
        if (const Json* seed = find(root, "seed")) scene.seed = readSeed(*seed, "/seed");
        scene.spheres = readList(root, "spheres", &SceneReader::readSphere);
        scene.generators = readList(root, "generate", &SceneReader::readGenerator);
        scene.emitters = readList(root, "emitters", &SceneReader::readEmitter);
        readSavedState(root, scene);
        readParameters(root, scene);
        scene.claims = readList(root, "claims", &SceneReader::readClaim);
        checkClaims(scene);
        readCompare(root, scene);
        return scene;
    }

  private:
    static const Json* find(const Json& object, const char* key) {
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    const Json& required(const Json& object, const std::string& pointer, const char* key) const {
        const Json* value = find(object, key);
        if (!value) fail(pointer, where(pointer) + " needs \"" + key + "\"");
        return *value;
    }

    static std::string where(const std::string& pointer) {
        return pointer.empty() ? "the scene" : detail::readablePath(pointer);
    }

    void checkKeys(const Json& v, const std::string& pointer, const Keys& allowed) const {
        if (!v.is_object()) {
            fail(pointer, where(pointer) + " must be an object {...}, got " + typeName(v));
        }
        for (const auto& item : v.items()) {
            const std::string& key = item.key();
            if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
            fail(detail::childPointer(pointer, key),
                 detail::unknownName("key", key, allowed) + " (in " + where(pointer) + ")", true);
        }
    }

    // --- leaves: every number is finite (1e999 is refused by the parser) ---

    double number(const Json& v, const std::string& pointer) const {
        if (!v.is_number()) fail(pointer, where(pointer) + " must be a number, got " + typeName(v));
        return v.get<double>();
    }

    // A size, a mass, a density: positive, and within kPhysical of 1 (1e308 kg loaded, and
    // its energy was infinite at the first step).
    double positive(const Json& v, const std::string& pointer, const char* unit) const {
        const double x = number(v, pointer);
        if (!(x > 0)) {
            fail(pointer,
                 where(pointer) + " = " + formatNumber(x) + " must be positive (" + unit + ")");
        }
        if (x < 1.0 / kPhysical || x > kPhysical) outOfRange(pointer, x, 1.0 / kPhysical, kPhysical, unit);
        return x;
    }

    [[noreturn]] void outOfRange(const std::string& pointer, double x, double min, double max, const char* unit) const {
        fail(pointer, where(pointer) + " = " + formatNumber(x) + " is out of range [" + formatNumber(min) + ", " +
                          formatNumber(max) + "]" + (*unit ? std::string(" (") + unit + ")" : ""));
    }

    int readColorBy(const std::string& name, const std::string& pointer) const {
        for (std::size_t k = 0; k < std::size(kColorByNames); ++k) {
            if (name == kColorByNames[k]) return int(k);
        }
        fail(pointer, "color_by '" + name + "' is not a colouring; choices: id, speed, contact, penetration");
        return -1;
    }

    bool boolean(const Json& v, const std::string& pointer) const {
        if (!v.is_boolean()) fail(pointer, where(pointer) + " must be true or false, got " + typeName(v));
        return v.get<bool>();
    }

    double inRange(const Json& v, const std::string& pointer, double min, double max) const {
        const double x = integerOrNumber(v, pointer, false);
        if (x < min || x > max) {
            fail(pointer, where(pointer) + " = " + formatNumber(x) + " is out of range [" +
                              formatNumber(min) + ", " + formatNumber(max) + "]");
        }
        return x;
    }

    // A number; with `whole`, one without a fractional part.
    double integerOrNumber(const Json& v, const std::string& pointer, bool whole) const {
        // Compared as whole numbers: as a double, 2^53 + 1 rounds to 2^53 and passed, rounded.
        if (whole && v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(kMaxInteger)) {
            fail(pointer, where(pointer) + " = " + std::to_string(v.get<std::uint64_t>()) + " is out of range [0, " +
                              formatNumber(kMaxInteger) + "]");  // as written, not rounded to a double
        }
        const double x = number(v, pointer);
        if (whole && x != std::floor(x)) {
            fail(pointer, where(pointer) + " = " + formatNumber(x) + " must be a whole number");
        }
        return x;
    }

    void threeNumbers(const Json& v, const std::string& pointer) const {
        if (!v.is_array() || v.size() != 3) {
            fail(pointer, where(pointer) + " must be an array of 3 numbers [x, y, z], got " +
                              typeName(v) +
                              (v.is_array() ? " of " + std::to_string(v.size()) : ""));
        }
    }

    // [x, y, z], each positive (a size: its range is said as (0, 1e9], not [-1e9, 1e9]).
    glm::dvec3 positiveVector3(const Json& v, const std::string& pointer, const char* unit) const {
        threeNumbers(v, pointer);
        glm::dvec3 x;
        for (int i = 0; i < 3; ++i) x[i] = positive(v[i], pointer + "/" + std::to_string(i), unit);
        return x;
    }

    glm::dvec3 vector3(const Json& v, const std::string& pointer) const {
        threeNumbers(v, pointer);
        glm::dvec3 x;
        for (int i = 0; i < 3; ++i) {
            const std::string at = pointer + "/" + std::to_string(i);
            x[i] = number(v[i], at);
            if (std::abs(x[i]) > kPhysical) outOfRange(at, x[i], -kPhysical, kPhysical, "");
        }
        return x;
    }

    std::string string(const Json& object, const std::string& pointer, const char* key) const {
        const Json* v = find(object, key);
        if (!v) return {};
        const std::string at = detail::childPointer(pointer, key);
        if (!v->is_string()) fail(at, where(at) + " must be a string, got " + typeName(*v));
        return v->get<std::string>();
    }

    double nonNegative(const Json& v, const std::string& pointer, const char* unit) const {
        const double x = number(v, pointer);
        if (!(x >= 0)) {
            fail(pointer,
                 where(pointer) + " = " + formatNumber(x) + " must be >= 0 (" + unit + ")");
        }
        return x;
    }

    // The range of the table's "seed" parameter.
    std::uint64_t readSeed(const Json& v, const std::string& pointer) const {
        const Parameter& seed = *findParameter("seed");
        integerOrNumber(v, pointer, true);
        return static_cast<std::uint64_t>(inRange(v, pointer, seed.min, seed.max));
    }

    // --- the parts of a scene ---

    template <typename T>
    std::vector<T> readList(const Json& root, const char* key,
                            T (SceneReader::*readOne)(const Json&, const std::string&)
                                const) const {
        std::vector<T> out;
        const Json* list = find(root, key);
        if (!list) return out;
        const std::string pointer = detail::childPointer("", key);
        if (!list->is_array()) {
            fail(pointer, std::string(key) + " must be an array [...], got " + typeName(*list));
        }
        for (std::size_t i = 0; i < list->size(); ++i) {
            out.push_back((this->*readOne)((*list)[i], detail::childPointer(pointer, i)));
        }
        return out;
    }

    std::optional<Box> readBox(const Json& v, const std::string& pointer) const {
        if (v.is_null()) return std::nullopt;
        checkKeys(v, pointer, kBoxKeys);
        Box box;
        if (const Json* size = find(v, "size")) box.size = positiveVector3(*size, pointer + "/size", "m");
        if (const Json* tilt = find(v, "tilt")) {
            box.tilt = inRange(*tilt, pointer + "/tilt", -kMaxTilt, kMaxTilt);
        }
        return box;
    }

    physics::Plane readPlane(const Json& v, const std::string& pointer) const {
        checkKeys(v, pointer, kPlaneKeys);
        physics::Plane plane;
        plane.point = vector3(required(v, pointer, "point"), pointer + "/point");
        const glm::dvec3 normal = vector3(required(v, pointer, "normal"), pointer + "/normal");
        const auto unit = detail::unitNormal(normal);
        if (!unit) {
            fail(pointer + "/normal",
                 where(pointer + "/normal") + " is zero: a plane needs a direction");
        }
        plane.normal = *unit;
        if (const Json* thickness = find(v, "thickness")) {
            plane.thickness = nonNegative(*thickness, pointer + "/thickness", "m");
        }
        return plane;
    }

    physics::Plane readMirror(const Json& v, const std::string& pointer) const {
        checkKeys(v, pointer, kMirrorKeys);
        return readPlane(v, pointer);
    }

    Sphere readSphere(const Json& v, const std::string& pointer) const {
        checkKeys(v, pointer, kSphereKeys);
        Sphere s;
        s.p = vector3(required(v, pointer, "p"), pointer + "/p");
        if (const Json* vel = find(v, "v")) s.v = vector3(*vel, pointer + "/v");
        if (const Json* r = find(v, "r")) s.r = positive(*r, pointer + "/r", "m");
        if (const Json* m = find(v, "m")) s.m = positive(*m, pointer + "/m", "kg");
        return s;
    }

    Generator readGenerator(const Json& v, const std::string& pointer) const {
        checkKeys(v, pointer, kGeneratorKeys);
        Generator g;
        if (find(v, "kind")) g.kind = readKind(v, pointer);
        const std::string countAt = pointer + "/count";
        integerOrNumber(required(v, pointer, "count"), countAt, true);
        g.count = static_cast<int>(inRange(v["count"], countAt, 0, kMaxGeneratedCount));
        if (const Json* region = find(v, "region")) readRegion(*region, pointer + "/region", g);
        if (const Json* radius = find(v, "radius")) readRadius(*radius, pointer + "/radius", g);
        readMass(v, pointer, g);
        if (const Json* vel = find(v, "velocity")) {
            g.velocity = vector3(*vel, pointer + "/velocity");
        }
        if (const Json* spread = find(v, "velocitySpread")) {
            g.velocitySpread = nonNegative(*spread, pointer + "/velocitySpread", "m/s");
        }
        if (const Json* seed = find(v, "seed")) g.seed = readSeed(*seed, pointer + "/seed");
        return g;
    }

    Emitter readEmitter(const Json& v, const std::string& pointer) const {
        checkKeys(v, pointer, kEmitterKeys);
        Emitter e;
        const Parameter& period = *findParameter("emit_period");
        required(v, pointer, "period");
        e.period = inRange(v["period"], pointer + "/period", period.min, period.max);
        e.position = vector3(required(v, pointer, "position"), pointer + "/position");
        if (const Json* vel = find(v, "velocity")) {
            e.velocity = vector3(*vel, pointer + "/velocity");
        }
        if (const Json* spread = find(v, "spread")) {
            e.spread = nonNegative(*spread, pointer + "/spread", "m/s");
        }
        if (const Json* radius = find(v, "radius")) {
            const auto [lo, hi] = readRadiusRange(*radius, pointer + "/radius");
            e.radiusMin = lo;
            e.radiusMax = hi;
        }
        const auto [rule, value] = readMassRule(v, pointer);
        e.massRule = rule;
        if (rule == MassRule::Fixed) e.mass = value;
        if (rule == MassRule::Density && value > 0) e.density = value;
        if (const Json* max = find(v, "max")) {
            integerOrNumber(*max, pointer + "/max", true);
            e.max = static_cast<int>(inRange(*max, pointer + "/max", 0, kMaxGeneratedCount));
        }
        if (const Json* emitted = find(v, "emitted")) {
            integerOrNumber(*emitted, pointer + "/emitted", true);
            e.emitted = static_cast<int>(inRange(*emitted, pointer + "/emitted", 0, e.max));
        }
        return e;
    }

    Claim readClaim(const Json& v, const std::string& pointer) const {
        checkKeys(v, pointer, kClaimKeys);
        Claim c;
        c.says = string(v, pointer, "says");
        if (c.says.empty()) fail(pointer, where(pointer) + " needs \"says\": the words it checks");
        const std::string in = string(v, pointer, "in");
        if (in == "README") c.in = ClaimSource::Readme;
        else if (!in.empty() && in != "description") fail(pointer + "/in", "in must be \"description\" or \"README\"");
        c.measure = string(v, pointer, "measure");
        c.parameter = string(v, pointer, "name");
        c.take = find(v, "take") ? string(v, pointer, "take") : c.take;
        if (const Json* set = find(v, "set")) c.settings = strings(*set, pointer + "/set");
        if (const Json* ratio = find(v, "ratio_to")) c.ratioTo = strings(*ratio, pointer + "/ratio_to");
        if (const Json* sphere = find(v, "sphere")) {
            c.spheres = indices(*sphere, pointer + "/sphere");
            if (c.spheres.empty()) fail(pointer + "/sphere", "sphere lists no sphere: leave it out to watch every sphere");
        }
        if (const Json* plane = find(v, "plane")) c.plane = whole(*plane, pointer + "/plane", 0, 1000);
        if (const Json* nth = find(v, "nth")) c.nth = whole(*nth, pointer + "/nth", 1, kMaxGeneratedCount);
        c.from = optionalNumber(v, pointer, "from").value_or(0.0);
        c.to = optionalNumber(v, pointer, "to").value_or(c.from);
        c.near = optionalNumber(v, pointer, "near");
        c.within = optionalNumber(v, pointer, "within");
        c.min = optionalNumber(v, pointer, "min");
        c.max = optionalNumber(v, pointer, "max");
        return c;
    }

    std::optional<double> optionalNumber(const Json& object, const std::string& pointer, const char* key) const {
        const Json* v = find(object, key);
        if (!v) return std::nullopt;
        return number(*v, detail::childPointer(pointer, key));
    }

    std::vector<std::string> strings(const Json& v, const std::string& pointer) const {
        if (!v.is_array()) fail(pointer, where(pointer) + " must be an array of strings, got " + typeName(v));
        std::vector<std::string> out;
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (!v[i].is_string()) fail(detail::childPointer(pointer, i), where(pointer) + " must hold strings");
            out.push_back(v[i].get<std::string>());
        }
        return out;
    }

    int whole(const Json& v, const std::string& pointer, int min, int max) const {
        integerOrNumber(v, pointer, true);
        return static_cast<int>(inRange(v, pointer, min, max));
    }

    // An index or an array of indices.
    std::vector<int> indices(const Json& v, const std::string& pointer) const {
        if (!v.is_array()) return {whole(v, pointer, 0, kMaxGeneratedCount)};
        std::vector<int> out;
        for (std::size_t i = 0; i < v.size(); ++i) {
            out.push_back(whole(v[i], detail::childPointer(pointer, i), 0, kMaxGeneratedCount));
        }
        return out;
    }

    // "compare": the other views' overrides, checked as --compare checks them.
    void readCompare(const Json& root, Scene& scene) const {
        if (!find(root, "compare")) return;
        scene.compare = {string(root, "", "compare")};
        if (const std::string error = checkCompare(scene, scene.compare); !error.empty()) {
            fail("/compare", "compare: " + error);
        }
    }

    // Each claim's settings, meter and bounds make sense for this scene.
    void checkClaims(const Scene& scene) const {
        for (std::size_t i = 0; i < scene.claims.size(); ++i) {
            const std::string error = checkClaimForm(scene.claims[i], scene);
            if (!error.empty()) fail(detail::childPointer("/claims", i), "claims[" + std::to_string(i) + "]: " + error);
        }
    }

    GeneratorKind readKind(const Json& v, const std::string& pointer) const {
        const std::string kind = string(v, pointer, "kind");
        if (kind == "lattice") return GeneratorKind::Lattice;
        if (kind == "random") return GeneratorKind::Random;
        fail(pointer + "/kind", detail::unknownName("kind", kind, kKinds));
    }

    // {"min": [..], "max": [..]}, m, max above min on every axis.
    std::pair<glm::dvec3, glm::dvec3> region(const Json& v, const std::string& pointer) const {
        checkKeys(v, pointer, kRegionKeys);
        const glm::dvec3 min = vector3(required(v, pointer, "min"), pointer + "/min");
        const glm::dvec3 max = vector3(required(v, pointer, "max"), pointer + "/max");
        for (int i = 0; i < 3; ++i) {
            if (min[i] >= max[i]) {
                fail(pointer + "/max", where(pointer) + " max must exceed min in x, y and z (" + "xyz"[i] + ": min " +
                                           formatNumber(min[i]) + ", max " + formatNumber(max[i]) + ")");
            }
        }
        return {min, max};
    }

    void readRegion(const Json& v, const std::string& pointer, Generator& g) const {
        std::tie(g.regionMin, g.regionMax) = region(v, pointer);
    }

    SceneCamera readCamera(const Json& v, const std::string& pointer) const {
        checkKeys(v, pointer, kCameraKeys);
        SceneCamera camera;
        if (const Json* azimuth = find(v, "azimuth")) camera.azimuthDeg = inRange(*azimuth, pointer + "/azimuth", -360.0, 360.0);
        if (const Json* elevation = find(v, "elevation")) {
            camera.elevationDeg = inRange(*elevation, pointer + "/elevation", -kMostElevation, kMostElevation);
        }
        if (const Json* fits = find(v, "fits")) {
            Region region;
            std::tie(region.min, region.max) = this->region(*fits, pointer + "/fits");
            camera.fits = region;
        }
        return camera;
    }

    // A fixed radius, or [min, max] drawn uniformly, in m.
    std::pair<double, double> readRadiusRange(const Json& v, const std::string& pointer) const {
        if (v.is_number()) {
            const double r = positive(v, pointer, "m");
            return {r, r};
        }
        if (!v.is_array() || v.size() != 2) {
            fail(pointer, where(pointer) + " must be a number or [min, max], got " + typeName(v));
        }
        const double lo = positive(v[0], pointer + "/0", "m");
        const double hi = positive(v[1], pointer + "/1", "m");
        if (lo > hi) fail(pointer, where(pointer) + " must be [min, max] with min <= max");
        return {lo, hi};
    }

    void readRadius(const Json& v, const std::string& pointer, Generator& g) const {
        const auto [lo, hi] = readRadiusRange(v, pointer);
        g.radiusMin = lo;
        g.radiusMax = hi;
    }

    // "density" (kg/m^3) or "mass" (kg), not both: the rule and its value (0: neither given).
    std::pair<MassRule, double> readMassRule(const Json& v, const std::string& pointer) const {
        const Json* density = find(v, "density");
        const Json* mass = find(v, "mass");
        if (density && mass) {
            fail(pointer + "/mass", where(pointer) + " gives both density and mass: give one",
                 true);
        }
        if (mass) return {MassRule::Fixed, positive(*mass, pointer + "/mass", "kg")};
        if (density) return {MassRule::Density, positive(*density, pointer + "/density", "kg/m^3")};
        return {MassRule::Density, 0.0};
    }

    void readMass(const Json& v, const std::string& pointer, Generator& g) const {
        const auto [rule, value] = readMassRule(v, pointer);
        g.massRule = rule;
        if (rule == MassRule::Fixed) g.mass = value;
        if (rule == MassRule::Density && value > 0) g.density = value;
    }

    void readSavedState(const Json& root, Scene& scene) const {
        if (const Json* time = find(root, "time")) {
            scene.snapshot = true;
            scene.time = nonNegative(*time, "/time", "s");
            if (scene.time > kPhysical) outOfRange("/time", scene.time, 0.0, kPhysical, "s");
        }
        if (const Json* steps = find(root, "steps")) {
            integerOrNumber(*steps, "/steps", true);
            scene.stepCount =
                static_cast<std::uint64_t>(inRange(*steps, "/steps", 0.0, kMaxInteger));
        }
    }

    // Live parameters first; count, radius and seed after, as they act on the
    // generators and the seed read above.
    void readParameters(const Json& root, Scene& scene) const {
        const Json* parameters = find(root, "parameters");
        if (!parameters) return;
        checkKeys(*parameters, "/parameters", parameterNames());
        for (Applies pass : {Applies::Live, Applies::Restart}) {
            for (const auto& item : parameters->items()) {
                const Parameter& p = *findParameter(item.key());
                if (p.applies == pass) readParameter(p, item.value(), root, scene);
            }
        }
        // Once all are set, as --set does: a setting for another method is refused, not
        // kept unused ("shock": "on" with the continuous method).
        for (const auto& item : parameters->items()) {
            const std::string setting = item.key() + "=" + formatValue(*findParameter(item.key()), scene);
            if (const std::string why = settingsThatActOnNothing(scene, {setting}); !why.empty()) {
                fail(detail::childPointer("/parameters", item.key()), why);
            }
        }
    }

    void readParameter(const Parameter& p, const Json& v, const Json& root, Scene& scene) const {
        const std::string pointer = detail::childPointer("/parameters", p.name);
        if (p.name == "seed" && find(root, "seed")) {
            fail(pointer, "seed is given twice: at the top level and in parameters", true);
        }
        double value = 0.0;
        if (p.kind == ParameterKind::Choice) {
            if (!v.is_string()) {
                fail(pointer, where(pointer) + " must be one of " + detail::joinNames(p.choices) +
                                  ", got " + typeName(v));
            }
            const std::string name = v.get<std::string>();
            value = choiceIndex(p, name);
            if (value < 0) {
                fail(pointer,
                     detail::unknownName(std::string(p.name) + " choice", name, p.choices));
            }
        } else {
            value = integerOrNumber(v, pointer, false);
        }
        const std::string error = setValue(p, scene, value);
        if (!error.empty()) fail(pointer, error);
    }

    std::string_view text_;
    std::string file_;
};

// The length in bytes of the character at text[at] when it is printable UTF-8 (a tab, or
// U+0020 on, without DEL and the C1 controls), else 0: a byte out of place, a character cut
// short, an overlong form, a surrogate or a code point past U+10FFFF.
std::size_t printableCharacterLength(const std::string& text, std::size_t at) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
    const std::size_t length = byte(0) < 0x80 ? 1 : (byte(0) >> 5) == 0x6 ? 2 : (byte(0) >> 4) == 0xE ? 3 : (byte(0) >> 3) == 0x1E ? 4 : 0;
    if (length == 0 || at + length > text.size()) return 0;
    char32_t code = length == 1 ? byte(0) : byte(0) & (0x7F >> length);
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(k) & 0xC0) != 0x80) return 0;
        code = (code << 6) | (byte(k) & 0x3F);
    }
    constexpr char32_t kLeast[] = {0, 0, 0x80, 0x800, 0x10000};  // below these, an overlong form
    const bool valid = code >= kLeast[length] && code <= 0x10FFFF && (code < 0xD800 || code > 0xDFFF);
    const bool printable = code == '\t' || (code >= 0x20 && (code < 0x7F || code > 0x9F));
    return valid && printable ? length : 0;
}

// `text` with each byte that is not part of a printable UTF-8 character written as \xFF:
// a binary file's last byte read had been printed raw, as a replacement mark or worse.
std::string bytesShown(const std::string& text) {
    std::string shown;
    for (std::size_t at = 0; at < text.size();) {
        if (const std::size_t length = printableCharacterLength(text, at); length > 0) {
            shown.append(text, at, length);
            at += length;
        } else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02X", static_cast<unsigned char>(text[at]));
            shown += escaped;
            ++at;
        }
    }
    return shown;
}

// nlohmann's message without its "[json.exception...] parse error at line 3, column 6: ",
// what it last read cut to its end (an unquoted key repeated the whole description), and
// the likely slip where its words do not name it: a comma missing or one too many.
std::string syntaxMessage(const Json::parse_error& e) {
    const std::string what = e.what();
    const auto start = what.find(": ", what.find("parse error"));
    std::string message = start == std::string::npos ? what : what.substr(start + 2);
    constexpr std::size_t kShownRead = 40;  // characters
    const std::string read = "last read: '";
    if (const std::size_t from = message.find(read); from != std::string::npos) {
        const std::size_t begin = from + read.size(), end = message.find("'; ", begin);
        if (end != std::string::npos && end - begin > kShownRead) {
            std::size_t cut = end - kShownRead;
            while (cut < end && (static_cast<unsigned char>(message[cut]) & 0xC0) == 0x80) ++cut;  // a character whole
            message.replace(begin, cut - begin, "...");
        }
    }
    const bool closedEarly = message.find("unexpected ']'") != std::string::npos || message.find("unexpected '}'") != std::string::npos;
    if (closedEarly) {
        // "unexpected '}'; expected ']'" is a bracket closed by the wrong one, not a comma
        if (message.find("; expected '[', '{', or a literal") != std::string::npos) message += " (a comma after the last item?)";
    } else if (message.find("unexpected string literal; expected '}'") != std::string::npos ||
               message.find("; expected ']'") != std::string::npos) {
        message += " (a comma missing before it?)";
    }
    return "invalid JSON: " + bytesShown(message);
}

Json parseJson(std::string_view text, const SceneReader& reader) {
    try {
        return Json::parse(text.begin(), text.end());
    } catch (const Json::parse_error& e) {
        reader.failAt(e.byte > 0 ? e.byte - 1 : 0, syntaxMessage(e));
    } catch (const Json::out_of_range&) {
        reader.failAt(detail::nonFiniteNumber(text).value_or(0),
                      "number out of the range of a double (it would be infinite)");
    }
}

// --- writing ---

std::string dump(const Json& v) { return v.dump(-1, ' ', false, Json::error_handler_t::replace); }

std::string vectorText(const glm::dvec3& v) { return dump(Json::array({v.x, v.y, v.z})); }

std::string boxText(const std::optional<Box>& box) {
    if (!box) return "null";
    return "{\"size\": " + vectorText(box->size) + ", \"tilt\": " + dump(box->tilt) + "}";
}

bool cameraGiven(const SceneCamera& camera) { return camera.azimuthDeg || camera.elevationDeg || camera.fits; }

std::string cameraText(const SceneCamera& camera) {
    std::string text;
    const auto add = [&](const std::string& item) { text += (text.empty() ? "{" : ", ") + item; };
    if (camera.azimuthDeg) add("\"azimuth\": " + dump(*camera.azimuthDeg));
    if (camera.elevationDeg) add("\"elevation\": " + dump(*camera.elevationDeg));
    if (camera.fits) add("\"fits\": {\"min\": " + vectorText(camera.fits->min) + ", \"max\": " + vectorText(camera.fits->max) + "}");
    return text + "}";
}

std::string planesText(const std::vector<physics::Plane>& planes, std::size_t first) {
    std::string out;
    for (std::size_t k = first; k < planes.size(); ++k) {
        out += out.empty() ? "\n    " : ",\n    ";
        const physics::Plane& plane = planes[k];
        out +=
            "{\"point\": " + vectorText(plane.point) + ", \"normal\": " + vectorText(plane.normal);
        if (plane.thickness > 0) out += ", \"thickness\": " + dump(plane.thickness);
        out += "}";
    }
    return "[" + out + (out.empty() ? "]" : "\n  ]");
}

// The Live parameters that act in the scene (a file that sets one for another method is
// refused); count, radius and seed belong to generators and the top level, emit_period to
// the first emitter.
std::string parametersText(const Scene& scene) {
    std::string out;
    for (const Parameter& p : parameterTable()) {
        if (p.applies != Applies::Live || p.name == "emit_period" || !p.availableIn(scene)) continue;
        const std::string value = formatValue(p, scene);
        out += out.empty() ? "\n    " : ",\n    ";
        out += dump(std::string(p.name)) + ": ";
        if (p.kind == ParameterKind::Choice) {
            out += dump(value);
        } else if (p.kind == ParameterKind::Integer) {
            out += value;
        } else {
            out += dump(p.get(scene));  // the shortest decimal that reads back the same
        }
    }
    return "{" + out + "\n  }";
}

std::string spheresText(const physics::World& world) {
    std::string out;
    for (std::size_t i = 0; i < world.size(); ++i) {
        out += out.empty() ? "\n    " : ",\n    ";
        out += "{\"p\": " + vectorText(world.position[i]) +
               ", \"v\": " + vectorText(world.velocity[i]) + ", \"r\": " + dump(world.radius[i]) +
               ", \"m\": " + dump(world.mass[i]) + "}";
    }
    return "[" + out + (out.empty() ? "]" : "\n  ]");
}

// The emitters, each with the count it has emitted into `world` so far.
std::string emittersText(const Scene& scene, const physics::World& world) {
    const std::vector<int> counts = emittedCounts(scene, world);
    std::string out;
    for (std::size_t i = 0; i < scene.emitters.size(); ++i) {
        const Emitter& e = scene.emitters[i];
        out += out.empty() ? "\n    " : ",\n    ";
        out += "{\"period\": " + dump(e.period) + ", \"position\": " + vectorText(e.position) +
               ", \"velocity\": " + vectorText(e.velocity) + ", \"spread\": " + dump(e.spread) +
               ", \"radius\": " +
               (e.radiusMin == e.radiusMax ? dump(e.radiusMin)
                                           : dump(Json::array({e.radiusMin, e.radiusMax}))) +
               (e.massRule == MassRule::Fixed ? ", \"mass\": " + dump(e.mass)
                                              : ", \"density\": " + dump(e.density)) +
               ", \"max\": " + std::to_string(e.max) +
               ", \"emitted\": " + std::to_string(counts[i]) + "}";
    }
    return "[" + out + (out.empty() ? "]" : "\n  ]");
}

void checkFinite(const physics::World& world) {
    auto finite = [](const glm::dvec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    for (std::size_t i = 0; i < world.size(); ++i) {
        if (!finite(world.position[i]) || !finite(world.velocity[i]) ||
            !std::isfinite(world.radius[i]) || !std::isfinite(world.mass[i])) {
            throw SceneError("cannot save: sphere " + std::to_string(i) +
                             " has a non-finite position, velocity, radius or mass");
        }
    }
    if (!std::isfinite(world.time)) throw SceneError("cannot save: the time is not finite");
}

}  // namespace

Scene parseScene(std::string_view text, const std::string& filename) {
    SceneReader reader(text, filename);
    const Json root = parseJson(text, reader);
    if (const auto duplicate = detail::duplicateKey(text)) {
        reader.failAt(duplicate->offset,
                      "key '" + detail::readablePath(duplicate->pointer) + "' appears twice");
    }
    if (!root.is_object()) {
        reader.fail("", "a scene must be a JSON object {...}, got " + typeName(root));
    }
    Scene scene;
    try {
        scene = reader.read(root);
        scene.textCount = builtSphereCount(scene);
        buildWorld(scene);  // overlaps, spheres outside the box, regions that cannot hold count
        stampClaimVariants(scene);
    } catch (const SceneError& e) {
        if (e.path().empty()) throw;  // already "file:line:col: ..."
        reader.fail(e.path(), e.what());
    } catch (const nlohmann::json::exception& e) {
        reader.failAt(0, e.what());  // a check above missed a case: still one line, no crash
    }
    return scene;
}

namespace {

// bytes: far above a saved state of the most spheres the demo runs (about 300 bytes a sphere).
constexpr std::uintmax_t kMostSceneBytes = std::uintmax_t(1) << 30;

}  // namespace

Scene loadScene(const std::string& path) {
    // Checked before it is opened: a pipe would block the open, and a device (/dev/zero,
    // typed into the panel's file field) would be read until memory ran out.
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (fs::exists(status) && !fs::is_regular_file(status)) {
        throw SceneError(path + ":1:1: " + (fs::is_directory(status) ? "is a folder" : "is not a regular file") +
                         ", so no scene file");
    }
    if (const std::uintmax_t bytes = fs::is_regular_file(status) ? fs::file_size(path, error) : 0;
        !error && bytes > kMostSceneBytes) {
        throw SceneError(path + ":1:1: the scene file is larger than 1 GiB, far more than any scene");
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) throw SceneError(path + ":1:1: cannot open the scene file");
    std::ostringstream text;
    text << file.rdbuf();
    if (file.bad()) throw SceneError(path + ":1:1: cannot read the scene file");
    return parseScene(text.str(), path);
}

namespace {

// A state saved mid-run keeps its scene's text, which describes the run from its start:
// the text says so, once however often the state is saved again.
std::string savedDescription(const Scene& scene, const physics::World& world) {
    if (!(world.time > 0.0)) return scene.description;
    static const std::string kSaved = "Saved at t = ", kFromStart = " The scene's text, written for its start: ";
    std::string original = scene.description;
    if (original.rfind(kSaved, 0) == 0) {
        const std::size_t k = original.find(kFromStart);
        original = k == std::string::npos ? "" : original.substr(k + kFromStart.size());
    }
    char head[96];
    std::snprintf(head, sizeof head, "%.3f s (solver step %llu).", world.time,
                  static_cast<unsigned long long>(world.stepCount));
    std::string text = kSaved + head + (original.empty() ? "" : kFromStart + original);
    if (text.size() > kLongestDescription) {  // a text near the limit would not load again: its end is cut
        std::size_t cut = kLongestDescription - 3;  // bytes, the ellipsis' 3 after it
        while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a character
        text = text.substr(0, cut) + "\u2026";
    }
    return text;
}

}  // namespace

std::string sceneText(const Scene& scene, const physics::World& world) {
    checkFinite(world);
    std::ostringstream out;
    out << "{\n"
        << "  \"title\": " << dump(scene.title) << ",\n"
        << "  \"slide\": " << dump(scene.slide) << ",\n"
        << "  \"description\": " << dump(savedDescription(scene, world)) << ",\n"
        << "  \"box\": " << boxText(scene.box) << ",\n"
        << "  \"planes\": " << planesText(world.planes, std::size_t(world.boxPlaneCount)) << ",\n"
        << (scene.mirrors.empty() ? "" : "  \"mirror\": " + planesText(scene.mirrors, 0) + ",\n")
        << (cameraGiven(scene.camera) ? "  \"camera\": " + cameraText(scene.camera) + ",\n" : "")
        << (scene.timeScale != 1.0 ? "  \"time_scale\": " + dump(scene.timeScale) + ",\n" : "")
        << (scene.opensPaused ? "  \"paused\": true,\n" : "")
        << (scene.colorBy >= 0 ? std::string("  \"color_by\": \"") + kColorByNames[scene.colorBy] + "\",\n" : "")
        << "  \"parameters\": " << parametersText(scene) << ",\n"
        << "  \"seed\": " << scene.seed << ",\n"
        << "  \"time\": " << dump(world.time) << ",\n"
        << "  \"steps\": " << world.stepCount << ",\n"
        << "  \"emitters\": " << emittersText(scene, world) << ",\n"
        << "  \"spheres\": " << spheresText(world) << "\n"
        << "}\n";
    return out.str();
}

void saveScene(const std::string& path, const Scene& scene, const physics::World& world) {
    // A state the loader would refuse is not written: a file that cannot be opened again.
    for (std::size_t i = 0; i < world.size(); ++i) {
        const glm::dvec3 &p = world.position[i], &v = world.velocity[i];
        for (double x : {p.x, p.y, p.z, v.x, v.y, v.z}) {
            if (!(std::abs(x) <= kPhysical)) {
                throw SceneError(path + ": sphere #" + std::to_string(i) +
                                 " is beyond what a scene file holds (coordinates and speeds up to 1e9 m and m/s); "
                                 "not saved");
            }
        }
    }
    const std::string text = sceneText(scene, world);
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw SceneError(path + ": is a folder, not a file: not saved");
    if (!platform::writeWholeFile(path, text)) {  // a truncated scene would not load
        throw SceneError(path + ": cannot be written whole (a missing folder, no permission, or a full disk): not saved");
    }
}

}  // namespace scenes
