#include "assets/obj/obj_text_check.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>
#include <vector>

#include "assets/input_error.h"

namespace pt {
namespace {

using Tokens = std::vector<std::string_view>;

std::string readText(const std::string& path, const std::string& label) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(label + ": cannot open '" + path + "'");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Calls visit(line number, tokens) for every line with content; '#' starts a comment.
template <class Visit>
void forEachLine(const std::string& text, Visit visit) {
    size_t number = 0, start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + start, end - start);
        line = line.substr(0, line.find('#'));
        ++number;
        Tokens tokens;
        size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
            const size_t from = i;
            while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
            if (i > from) tokens.push_back(line.substr(from, i - from));
        }
        if (!tokens.empty()) visit(number, tokens);
        start = end + 1;
    }
}

[[noreturn]] void fail(const std::string& label, size_t line, const std::string& what) {
    throw InputError(label + ": line " + std::to_string(line) + ": " + what);
}

// Plain decimal notation only: tinyobjloader's parser reads hex floats, "inf" or "nan" as 0.
bool isNumber(std::string_view t, double& value) {
    size_t i = (!t.empty() && (t[0] == '+' || t[0] == '-')) ? 1 : 0;
    size_t digits = 0;
    auto skipDigits = [&] {
        while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i, ++digits;
    };
    skipDigits();
    if (i < t.size() && t[i] == '.') ++i, skipDigits();
    if (digits == 0) return false;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        ++i;
        if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
        const size_t before = digits;
        skipDigits();
        if (digits == before) return false;
    }
    if (i != t.size()) return false;
    const size_t sign = t[0] == '+' ? 1 : 0;
    const auto result = std::from_chars(t.data() + sign, t.data() + t.size(), value);
    return result.ec == std::errc() && std::isfinite(value);
}

// tokens[first...] must be between `min` and `max` finite numbers; returns the first.
double numbers(const Tokens& tokens, size_t first, size_t min, size_t max, size_t line,
               const std::string& label) {
    const size_t count = tokens.size() - first;
    if (count < min || count > max) {
        fail(label, line,
             std::string(tokens[0]) + " expects " + std::to_string(min) +
                 (max > min ? " to " + std::to_string(max) : "") + " numbers, got " + std::to_string(count));
    }
    double value = 0.0, firstValue = 0.0;
    for (size_t i = first; i < tokens.size(); ++i) {
        if (!isNumber(tokens[i], value)) {
            fail(label, line, "'" + std::string(tokens[i]) + "' is not a finite number");
        }
        if (i == first) firstValue = value;
    }
    return firstValue;
}

// Face references: 1-based, negative counts back from the latest; positive ones may point
// forward, so the largest is checked against the totals at the end.
struct FaceIndexCheck {
    size_t count = 0;  // elements so far
    long long maxPositive = 0;
    size_t maxLine = 0;

    void check(long long index, size_t line, const std::string& label, const char* kind) {
        if (index == 0) fail(label, line, std::string(kind) + " index 0 (OBJ indices start at 1)");
        if (index < 0 && size_t(-index) > count) {
            fail(label, line,
                 std::string(kind) + " index " + std::to_string(index) + " reaches before the first " + kind);
        }
        if (index > maxPositive) maxPositive = index, maxLine = line;
    }
    void finish(const std::string& label, const char* kind) const {
        if (maxPositive > 0 && size_t(maxPositive) > count) {
            fail(label, maxLine,
                 std::string(kind) + " index " + std::to_string(maxPositive) + " is past the " +
                     std::to_string(count) + " " + kind + " entries in the file");
        }
    }
};

void checkFaceCorner(std::string_view corner, size_t line, const std::string& label,
                     FaceIndexCheck (&checks)[3]) {
    static const char* kKinds[3] = {"v", "vt", "vn"};
    size_t part = 0, start = 0;
    while (start <= corner.size() && part < 3) {
        size_t end = corner.find('/', start);
        if (end == std::string_view::npos) end = corner.size();
        const std::string_view text = corner.substr(start, end - start);
        if (!text.empty() || part == 0) {
            long long index = 0;
            const auto r = std::from_chars(text.data(), text.data() + text.size(), index);
            if (r.ec != std::errc() || r.ptr != text.data() + text.size()) {
                fail(label, line, "'" + std::string(corner) + "' is not a face corner (v/vt/vn)");
            }
            checks[part].check(index, line, label, kKinds[part]);
        }
        start = end + 1;
        ++part;
    }
    if (start <= corner.size()) fail(label, line, "'" + std::string(corner) + "' has too many parts");
}

void checkMtl(const std::string& path, const std::string& label, ObjTextFacts& facts) {
    static const std::set<std::string_view> kColors = {"Ka", "Kd", "Ks", "Ke", "Tf", "Kt"};
    static const std::set<std::string_view> kScalars = {"Ns", "Ni", "d",  "Tr",  "illum", "sharpness", "Pr",
                                                        "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor"};
    std::string material;
    const std::string text = readText(path, label);
    forEachLine(text, [&](size_t line, const Tokens& t) {
        if (t[0] == "newmtl") {
            material = t.size() > 1 ? std::string(t[1]) : "";
        } else if (kColors.count(t[0]) && (t.size() < 2 || t[1] != "spectral")) {
            const size_t first = t.size() > 1 && t[1] == "xyz" ? 2 : 1;
            const double v = numbers(t, first, 1, 3, line, label);
            if (t.size() - first == 2) fail(label, line, std::string(t[0]) + " expects 1 or 3 numbers");
            if (t.size() - first == 1) facts.grayColors[{material, std::string(t[0])}] = float(v);
        } else if (kScalars.count(t[0])) {
            numbers(t, t.size() > 1 && t[1] == "-halo" ? 2 : 1, 1, 1, line, label);
        }
    });
}

}  // namespace

ObjTextFacts checkObjText(const std::string& objPath, const std::string& label) {
    ObjTextFacts facts;
    FaceIndexCheck checks[3];  // v, vt, vn
    std::vector<std::string> mtlFiles;
    const std::string text = readText(objPath, label);
    forEachLine(text, [&](size_t line, const Tokens& t) {
        if (t[0] == "v") {
            numbers(t, 1, 3, 7, line, label);  // x y z [w] or x y z r g b
            ++checks[0].count;
        } else if (t[0] == "vt") {
            numbers(t, 1, 1, 3, line, label);
            ++checks[1].count;
        } else if (t[0] == "vn") {
            numbers(t, 1, 3, 3, line, label);
            ++checks[2].count;
        } else if (t[0] == "f") {
            if (t.size() < 4) fail(label, line, "a face needs at least 3 corners");
            for (size_t i = 1; i < t.size(); ++i) checkFaceCorner(t[i], line, label, checks);
        } else if (t[0] == "l" || t[0] == "p") {
            ++facts.linesAndPoints;
        } else if (t[0] == "mtllib") {
            for (size_t i = 1; i < t.size(); ++i) mtlFiles.emplace_back(t[i]);
        }
    });
    checks[0].finish(label, "v");
    checks[1].finish(label, "vt");
    checks[2].finish(label, "vn");
    const std::filesystem::path dir = std::filesystem::path(objPath).parent_path();
    for (const std::string& name : mtlFiles) {
        const std::filesystem::path mtl = dir / name;
        std::error_code error;
        if (std::filesystem::is_regular_file(mtl, error)) {
            checkMtl(mtl.string(), mtl.filename().string(), facts);
        }
    }
    return facts;
}

}  // namespace pt
