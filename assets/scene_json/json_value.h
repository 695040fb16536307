#pragma once
// JSON values with their location, for readers whose every error must name the file and the
// JSON path of the bad element ("cornell.json: objects[3].transform.scale: expected 3
// numbers"). Internal to pt_assets: nlohmann::json does not appear in public headers.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "render/math/vec.h"

namespace pt {

// Keys keep their document order, so the writer's output is in the order it builds it and
// an unknown-key report names the first offending key as the user reads the file.
using Json = nlohmann::ordered_json;

// Parses `text`. Syntax errors name the line and column; a key given twice in one object is
// an error naming its JSON path (nlohmann would silently keep the last one).
Json parseJsonText(const std::string& text, const std::string& fileName);

// Allowed values of a number, stated in messages ("expected a number in [0, 1], got 1.5").
enum class NumberRange { Any, NonNegative, Positive, AtLeastOne, Unit, SignedUnit };

// The number in `range` nearest to v, finite (NaN: the range's lowest), so that an editor can
// keep values the reader would refuse out of what it saves.
float nearestInRange(float v, NumberRange range);

// A value inside a parsed document and the path that reached it. Holds a reference into
// the document, which must outlive it.
class JsonValue {
public:
    JsonValue(const Json& value, std::string path, const std::string& fileName)
        : value_(&value), path_(std::move(path)), fileName_(&fileName) {}

    const Json& json() const { return *value_; }
    const std::string& path() const { return path_; }
    const std::string& fileName() const { return *fileName_; }
    std::string childPath(const std::string& key) const;

    // Throws InputError "<file>: <path>: <what>" (no path part at the document root).
    [[noreturn]] void fail(const std::string& what) const;
    // Describes the value for messages: scalars as written, containers by type.
    std::string describe() const;

    // Each checks the type (and range) and fails with this value's path otherwise.
    float asFloat(NumberRange range = NumberRange::Any) const;  // finite as a 32-bit float
    uint32_t asUint(uint32_t minimum = 0, uint32_t maximum = UINT32_MAX) const;
    int64_t asInt() const;
    bool asBool() const;
    std::string asString() const;  // non-empty
    std::vector<JsonValue> asArray() const;
    std::vector<float> asFloats(size_t count, NumberRange range = NumberRange::Any) const;
    Vec2 asVec2(NumberRange range = NumberRange::Any) const;
    Vec3 asVec3(NumberRange range = NumberRange::Any) const;

private:
    const Json* value_;
    std::string path_;
    const std::string* fileName_;
};

// Reads the keys of one JSON object and remembers which ones the reader asked for, so that
// finish() can report any other key: a typo such as "rouhgness" must not be silently
// ignored.
class ObjectReader {
public:
    explicit ObjectReader(const JsonValue& object);  // fails unless it is an object

    std::optional<JsonValue> get(const std::string& key);
    JsonValue require(const std::string& key);
    // Fails on the first key (in document order) that no get/require asked for.
    void finish() const;

private:
    JsonValue object_;
    std::vector<std::string> known_;
};

// Two-space indented text, except that arrays of numbers or strings stay on one line
// ("position": [0, 1, 5]), which is how people write scene files by hand.
std::string prettyJson(const Json& value);

// A float as a JSON number that reads back as exactly the same float and prints as the
// shortest decimal that does (0.8f is written 0.8, not 0.800000011920929).
Json floatToJson(float value);
Json vec2ToJson(Vec2 v);
Json vec3ToJson(Vec3 v);

// True when the two floats have the same bits; "default" and "unchanged" mean bit-identical
// here, so that a written scene reads back identical.
bool sameBits(float a, float b);
bool sameBits(Vec2 a, Vec2 b);
bool sameBits(Vec3 a, Vec3 b);

// Adds `key` to the object `out` when `value` is not bit-identical to `fallback`: the writer
// leaves defaults out.
void putIfChanged(Json& out, const char* key, float value, float fallback);
void putIfChanged(Json& out, const char* key, Vec2 value, Vec2 fallback);
void putIfChanged(Json& out, const char* key, Vec3 value, Vec3 fallback);

}  // namespace pt
