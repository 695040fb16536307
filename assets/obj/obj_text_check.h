#pragma once
// Checks an OBJ file and the MTL files it names, line by line, before tinyobjloader reads
// them. tinyobjloader 2.0rc10 reads a malformed number as 0 without a word, and reports
// out-of-range face indices (if at all) with the file's last line number; here each is an
// InputError naming the file and the line: "box.obj: line 12: '1.0x' is not a number".
// Internal to pt_assets.
#include <map>
#include <string>
#include <utility>

namespace pt {

struct ObjTextFacts {
    // MTL colors written with one number, the spec's gray shorthand ("Kd 0.5"), which
    // tinyobjloader reads as (0.5, 0, 0): (material name, keyword) -> value.
    std::map<std::pair<std::string, std::string>, float> grayColors;
    size_t linesAndPoints = 0;  // 'l' and 'p' elements, which are not rendered
};

// `label` starts every message (the OBJ's file name). MTL files are looked up next to the
// OBJ, as the importer tells tinyobjloader to; missing ones are left to its warning.
ObjTextFacts checkObjText(const std::string& objPath, const std::string& label);

}  // namespace pt
