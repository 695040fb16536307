#include "editor/file_browser.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace pt::editor {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool byName(const FileEntry& a, const FileEntry& b) {
    if (a.folder != b.folder) return a.folder;
    const std::string la = lower(a.name), lb = lower(b.name);
    return la != lb ? la < lb : a.name < b.name;
}

}  // namespace

FileBrowser::FileBrowser(std::vector<std::string> extensions) : extensions_(std::move(extensions)) {
    for (std::string& e : extensions_) e = lower(e);
}

bool FileBrowser::accepts(const std::string& fileName) const {
    if (extensions_.empty()) return true;
    const std::string extension = lower(fs::path(fileName).extension().string());
    return std::find(extensions_.begin(), extensions_.end(), extension) != extensions_.end();
}

bool FileBrowser::open(const std::string& folder) {
    std::error_code ec;
    const fs::path where = fs::weakly_canonical(fs::absolute(folder, ec), ec);
    std::vector<FileEntry> listed;
    fs::directory_iterator it(where, fs::directory_options::skip_permission_denied, ec);
    if (!ec && !fs::is_directory(where, ec)) ec = std::make_error_code(std::errc::not_a_directory);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!showHidden_ && !name.empty() && name[0] == '.') continue;
        std::error_code statError;
        FileEntry entry{name, it->is_directory(statError), 0};
        if (!entry.folder) {
            if (!accepts(name)) continue;
            const uintmax_t bytes = it->file_size(statError);
            entry.bytes = statError ? 0 : bytes;
        }
        listed.push_back(std::move(entry));
    }
    if (ec) {
        error_ = "cannot list " + where.string() + ": " + ec.message();
        return false;
    }
    std::sort(listed.begin(), listed.end(), byName);
    folder_ = where.string();
    entries_ = std::move(listed);
    error_.clear();
    return true;
}

bool FileBrowser::enter(const std::string& name) { return open((fs::path(folder_) / name).string()); }

bool FileBrowser::up() {
    const fs::path here(folder_);
    if (!here.has_relative_path()) return false;  // the root
    return open(here.parent_path().string());
}

void FileBrowser::setShowHidden(bool show) {
    showHidden_ = show;
    if (!folder_.empty()) refresh();
}

std::string FileBrowser::pathOf(const std::string& name) const { return (fs::path(folder_) / name).string(); }

std::vector<std::pair<std::string, std::string>> FileBrowser::crumbs() const {
    std::vector<std::pair<std::string, std::string>> out;
    fs::path prefix;
    for (const fs::path& part : fs::path(folder_)) {
        prefix /= part;
        if (part.empty()) continue;
        out.push_back({part.string(), prefix.string()});
    }
    return out;
}

std::string startFolder(const std::string& path) {
    std::error_code ec;  // a path that is not there is no folder: is_directory says false
    if (!path.empty()) {
        const fs::path p = fs::absolute(path, ec);
        if (fs::is_directory(p, ec)) return p.string();
        if (fs::is_directory(p.parent_path(), ec)) return p.parent_path().string();
    }
    const fs::path here = fs::current_path(ec);
    return ec ? std::string("/") : here.string();
}

std::string sizeText(uintmax_t bytes) {
    const char* units[] = {"B", "KB", "MB", "GB", "TB"};
    double value = double(bytes);
    int unit = 0;
    while (value >= 1000.0 && unit < 4) value /= 1000.0, ++unit;
    char text[32];
    std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, units[unit]);
    return text;
}

}  // namespace pt::editor
