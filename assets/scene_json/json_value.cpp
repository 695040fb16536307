#include "assets/scene_json/json_value.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <set>

#include "assets/input_error.h"
#include "assets/message_text.h"
#include "assets/scene_json/json_depth.h"

namespace pt {

namespace {

// Tracks the JSON path while nlohmann parses, to name the object that repeats a key.
class DuplicateKeyCheck {
public:
    explicit DuplicateKeyCheck(const std::string& fileName) : fileName_(fileName) {}

    bool onEvent(Json::parse_event_t event, const Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start: enter(false); break;
            case Json::parse_event_t::array_start: enter(true); break;
            case Json::parse_event_t::object_end:
            case Json::parse_event_t::array_end: frames_.pop_back(); break;
            case Json::parse_event_t::value: countElement(); break;
            case Json::parse_event_t::key: addKey(parsed.get<std::string>()); break;
        }
        return true;  // keep every value: this check only reads
    }

private:
    struct Frame {
        bool array = false;
        size_t elements = 0;  // arrays: elements seen so far
        std::string key;      // objects: the key being read
        std::set<std::string> keys;
    };

    void countElement() {
        if (!frames_.empty() && frames_.back().array) ++frames_.back().elements;
    }
    void enter(bool array) {
        countElement();
        frames_.push_back(Frame{array, 0, {}, {}});
    }
    void addKey(const std::string& key) {
        Frame& frame = frames_.back();
        frame.key = key;
        if (frame.keys.insert(key).second) return;
        const std::string path = pathOfInnermostObject();
        throw InputError(fileName_ + ": " + (path.empty() ? "" : path + ": ") + "duplicate key \"" + key +
                         "\"");
    }
    std::string pathOfInnermostObject() const {
        std::string path;
        for (size_t i = 0; i + 1 < frames_.size(); ++i) {
            const Frame& frame = frames_[i];
            if (frame.array) {
                path += "[" + std::to_string(frame.elements - 1) + "]";
            } else {
                path += (path.empty() ? "" : ".") + frame.key;
            }
        }
        return path;
    }

    const std::string& fileName_;
    std::vector<Frame> frames_;
};

// nlohmann's messages start with "[json.exception.parse_error.101] parse error at "; the
// rest ("line 3, column 6: syntax error ...") is what a user needs.
std::string withoutExceptionPrefix(const std::string& what) {
    for (const char* marker : {"parse error at ", "] "}) {
        const size_t at = what.find(marker);
        if (at != std::string::npos) return what.substr(at + std::strlen(marker));
    }
    return what;
}

const char* rangeText(NumberRange range) {
    switch (range) {
        case NumberRange::Any: return "a number";
        case NumberRange::NonNegative: return "a number >= 0";
        case NumberRange::Positive: return "a number > 0";
        case NumberRange::AtLeastOne: return "a number >= 1";
        case NumberRange::Unit: return "a number in [0, 1]";
        case NumberRange::SignedUnit: return "a number in [-1, 1]";
    }
    return "a number";
}

bool inRange(float v, NumberRange range) {
    switch (range) {
        case NumberRange::Any: return true;
        case NumberRange::NonNegative: return v >= 0.0f;
        case NumberRange::Positive: return v > 0.0f;
        case NumberRange::AtLeastOne: return v >= 1.0f;
        case NumberRange::Unit: return v >= 0.0f && v <= 1.0f;
        case NumberRange::SignedUnit: return v >= -1.0f && v <= 1.0f;
    }
    return true;
}

// Edits (insert, delete, substitute, swap two neighbours) between two keys: typos such as
// "rouhgness" are one swap away from the key meant.
size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        for (size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min(
                {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[a.size()][b.size()];
}

void writePretty(const Json& value, size_t indent, std::string& out) {
    if (!value.is_structured()) {
        out += value.dump();
        return;
    }
    const char* brackets = value.is_array() ? "[]" : "{}";
    const bool flat = value.is_array() && std::none_of(value.begin(), value.end(),
                                                       [](const Json& e) { return e.is_structured(); });
    if (value.empty() || flat) {
        out += brackets[0];
        for (size_t i = 0; i < value.size(); ++i) out += (i ? ", " : "") + value[i].dump();
        out += brackets[1];
        return;
    }
    out += brackets[0];
    for (auto it = value.begin(); it != value.end(); ++it) {
        out += (it == value.begin() ? "\n" : ",\n") + std::string(indent + 2, ' ');
        if (value.is_object()) out += Json(it.key()).dump() + ": ";
        writePretty(*it, indent + 2, out);
    }
    out += "\n" + std::string(indent, ' ') + brackets[1];
}

}  // namespace

std::string prettyJson(const Json& value) {
    std::string out;
    writePretty(value, 0, out);
    return out + "\n";
}

Json parseJsonText(const std::string& text, const std::string& fileName) {
    checkJsonDepth(text, fileName);  // before the parser and the value's destructor recurse
    DuplicateKeyCheck check(fileName);
    try {
        return Json::parse(
            text, [&](int, Json::parse_event_t event, Json& parsed) { return check.onEvent(event, parsed); });
    } catch (const Json::exception& e) {
        throw InputError(fileName + ": " + withoutExceptionPrefix(e.what()));
    }
}

std::string JsonValue::childPath(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
}

void JsonValue::fail(const std::string& what) const {
    throw InputError(fileName() + ": " + (path_.empty() ? "" : path_ + ": ") + what);
}

std::string JsonValue::describe() const {
    if (json().is_object()) return "an object";
    if (json().is_array()) return "an array";
    return shortened(json().dump(), 40);
}

float JsonValue::asFloat(NumberRange range) const {
    if (!json().is_number()) fail(std::string("expected ") + rangeText(range) + ", got " + describe());
    const float value = float(json().get<double>());
    if (!std::isfinite(value)) {
        fail("expected a finite number (within 32-bit float range), got " + describe());
    }
    if (!inRange(value, range)) fail(std::string("expected ") + rangeText(range) + ", got " + describe());
    return value;
}

int64_t JsonValue::asInt() const {
    if (json().is_number_unsigned()) {
        const uint64_t value = json().get<uint64_t>();
        if (value > uint64_t(std::numeric_limits<int64_t>::max())) fail("integer too large: " + describe());
        return int64_t(value);
    }
    if (!json().is_number_integer()) fail("expected an integer, got " + describe());
    return json().get<int64_t>();
}

uint32_t JsonValue::asUint(uint32_t minimum, uint32_t maximum) const {
    const int64_t value = asInt();
    if (value < int64_t(minimum) || value > int64_t(maximum)) {
        fail("expected an integer in [" + std::to_string(minimum) + ", " + std::to_string(maximum) +
             "], got " + describe());
    }
    return uint32_t(value);
}

bool JsonValue::asBool() const {
    if (!json().is_boolean()) fail("expected true or false, got " + describe());
    return json().get<bool>();
}

std::string JsonValue::asString() const {
    if (!json().is_string()) fail("expected a string, got " + describe());
    std::string value = json().get<std::string>();
    if (value.empty()) fail("expected a non-empty string");
    return value;
}

std::vector<JsonValue> JsonValue::asArray() const {
    if (!json().is_array()) fail("expected an array, got " + describe());
    std::vector<JsonValue> elements;
    for (size_t i = 0; i < json().size(); ++i) {
        elements.emplace_back(json()[i], path_ + "[" + std::to_string(i) + "]", fileName());
    }
    return elements;
}

std::vector<float> JsonValue::asFloats(size_t count, NumberRange range) const {
    const std::string expected = "expected " + std::to_string(count) + " numbers";
    if (!json().is_array() || json().size() != count) fail(expected);
    std::vector<float> values;
    for (const JsonValue& element : asArray()) {
        if (!element.json().is_number()) fail(expected);
        values.push_back(element.asFloat(range));
    }
    return values;
}

Vec2 JsonValue::asVec2(NumberRange range) const {
    const std::vector<float> v = asFloats(2, range);
    return {v[0], v[1]};
}

Vec3 JsonValue::asVec3(NumberRange range) const {
    const std::vector<float> v = asFloats(3, range);
    return {v[0], v[1], v[2]};
}

ObjectReader::ObjectReader(const JsonValue& object) : object_(object) {
    if (!object.json().is_object()) object.fail("expected an object, got " + object.describe());
}

std::optional<JsonValue> ObjectReader::get(const std::string& key) {
    known_.push_back(key);
    const auto it = object_.json().find(key);
    if (it == object_.json().end()) return std::nullopt;
    return JsonValue(*it, object_.childPath(key), object_.fileName());
}

JsonValue ObjectReader::require(const std::string& key) {
    std::optional<JsonValue> value = get(key);
    if (!value) object_.fail("missing key \"" + key + "\"");
    return *value;
}

void ObjectReader::finish() const {
    for (const auto& item : object_.json().items()) {
        const std::string& key = item.key();
        if (std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
        std::string message = "unknown key " + shortened(Json(key).dump());
        // Suggest the nearest allowed key when it is plausibly a typo of it.
        const size_t plausible = std::max<size_t>(1, key.size() / 4);
        size_t best = plausible + 1;
        std::string suggestion;
        for (const std::string& candidate : known_) {
            const size_t distance = editDistance(key, candidate);
            if (distance < best) {
                best = distance;
                suggestion = candidate;
            }
        }
        if (!suggestion.empty()) message += " (did you mean \"" + suggestion + "\"?)";
        object_.fail(message);
    }
}

Json floatToJson(float value) {
    // The shortest decimal for the float, read back as a double (which nlohmann then prints
    // as that same short decimal) unless decimal -> double -> float would round twice to
    // another float; the double equal to the float is always exact, if longer.
    char text[64];
    const std::to_chars_result result = std::to_chars(text, text + sizeof(text) - 1, value);
    *result.ptr = '\0';
    const double shortest = std::strtod(text, nullptr);
    return sameBits(float(shortest), value) ? Json(shortest) : Json(double(value));
}

Json vec2ToJson(Vec2 v) { return Json::array({floatToJson(v.x), floatToJson(v.y)}); }
Json vec3ToJson(Vec3 v) { return Json::array({floatToJson(v.x), floatToJson(v.y), floatToJson(v.z)}); }

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; }
bool sameBits(Vec2 a, Vec2 b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y); }
bool sameBits(Vec3 a, Vec3 b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z); }

void putIfChanged(Json& out, const char* key, float value, float fallback) {
    if (!sameBits(value, fallback)) out[key] = floatToJson(value);
}
void putIfChanged(Json& out, const char* key, Vec2 value, Vec2 fallback) {
    if (!sameBits(value, fallback)) out[key] = vec2ToJson(value);
}
void putIfChanged(Json& out, const char* key, Vec3 value, Vec3 fallback) {
    if (!sameBits(value, fallback)) out[key] = vec3ToJson(value);
}

float nearestInRange(float v, NumberRange range) {
    float lo = -std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::max();
    switch (range) {
        case NumberRange::Any: break;
        case NumberRange::NonNegative: lo = 0.0f; break;
        case NumberRange::Positive:
            lo = std::numeric_limits<float>::min();  // the smallest normal float: > 0 when read back
            break;
        case NumberRange::AtLeastOne: lo = 1.0f; break;
        case NumberRange::Unit:
            lo = 0.0f;
            hi = 1.0f;
            break;
        case NumberRange::SignedUnit:
            lo = -1.0f;
            hi = 1.0f;
            break;
    }
    return std::isnan(v) ? lo : std::min(std::max(v, lo), hi);
}

}  // namespace pt
