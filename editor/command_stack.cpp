#include "editor/command_stack.h"

namespace pt::editor {

SceneDelta CommandStack::execute(Document& doc, std::unique_ptr<EditCommand> command) {
    const SceneDelta changes = command->apply(doc);
    ++revision_;
    redo_.clear();
    const std::string key = command->mergeKey();
    if (mergeOpen_ && !key.empty() && !undo_.empty() && undo_.back().command->mergeKey() == key) {
        undo_.back().command->mergeFrom(*command);
    } else {
        undo_.push_back({nextId_++, std::move(command)});
    }
    mergeOpen_ = !key.empty();
    return changes;
}

SceneDelta CommandStack::cancelMerge(Document& doc) {
    if (!mergeOpen_ || undo_.empty()) return SceneChanges::None;
    mergeOpen_ = false;
    const SceneDelta changes = undo_.back().command->revert(doc);
    undo_.pop_back();
    ++revision_;
    return changes;
}

SceneDelta CommandStack::undo(Document& doc) {
    mergeOpen_ = false;
    if (undo_.empty()) return SceneChanges::None;
    Entry entry = std::move(undo_.back());
    undo_.pop_back();
    const SceneDelta changes = entry.command->revert(doc);
    ++revision_;
    redo_.push_back(std::move(entry));
    return changes;
}

SceneDelta CommandStack::redo(Document& doc) {
    mergeOpen_ = false;
    if (redo_.empty()) return SceneChanges::None;
    Entry entry = std::move(redo_.back());
    redo_.pop_back();
    const SceneDelta changes = entry.command->apply(doc);
    ++revision_;
    undo_.push_back(std::move(entry));
    return changes;
}

void CommandStack::clear() {
    undo_.clear();
    redo_.clear();
    markSaved();
}

void CommandStack::markSaved() {
    mergeOpen_ = false;
    savedState_ = currentState();
}

std::vector<std::string> CommandStack::undoLabels() const {
    std::vector<std::string> labels;
    for (const Entry& e : undo_) labels.push_back(e.command->label());
    return labels;
}

std::vector<std::string> CommandStack::redoLabels() const {
    std::vector<std::string> labels;
    for (auto e = redo_.rbegin(); e != redo_.rend(); ++e) labels.push_back(e->command->label());
    return labels;
}

}  // namespace pt::editor
