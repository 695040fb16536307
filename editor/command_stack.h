#pragma once
// CommandStack: the undo and redo history of a Document. Executing a command clears the redo
// history; a command whose mergeKey matches the open one on top of the undo stack folds into
// it until closeMerge() (the end of a slider drag, ImGui's IsItemDeactivatedAfterEdit).
#include <memory>
#include <string>
#include <vector>

#include "editor/edit_command.h"

namespace pt::editor {

class CommandStack {
public:
    // Applies `command` to `doc` and records it; returns what it changed.
    SceneDelta execute(Document& doc, std::unique_ptr<EditCommand> command);
    SceneDelta undo(Document& doc);  // None when there is nothing to undo
    SceneDelta redo(Document& doc);
    void closeMerge() { mergeOpen_ = false; }
    // Reverts the open drag's step and forgets it, as if the drag never happened (Esc during a
    // gizmo drag): no redo entry is left. None where no drag is open.
    SceneDelta cancelMerge(Document& doc);
    void clear();

    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    std::string undoLabel() const { return canUndo() ? undo_.back().command->label() : std::string(); }
    std::string redoLabel() const { return canRedo() ? redo_.back().command->label() : std::string(); }
    size_t undoDepth() const { return undo_.size(); }
    // The history list: the commands applied, oldest first (the last is the document's state),
    // and those undone, the next to redo first.
    std::vector<std::string> undoLabels() const;
    std::vector<std::string> redoLabels() const;
    // Grows with every command applied, undone or redone (each step of a drag too), so that
    // what is derived from the document can be kept until it changes.
    uint64_t revision() const { return revision_; }
    // Whether the document differs from when markSaved() was last called.
    bool modified() const { return savedState_ != currentState(); }
    // Also ends an open drag: what the drag does next is a change to the saved document.
    void markSaved();

private:
    // Each recorded command has an id no other ever gets, so "the state after command k"
    // names one document state even after commands are discarded (0: nothing applied).
    struct Entry {
        uint64_t id;
        std::unique_ptr<EditCommand> command;
    };
    uint64_t currentState() const { return undo_.empty() ? 0 : undo_.back().id; }

    std::vector<Entry> undo_, redo_;
    bool mergeOpen_ = false;
    uint64_t nextId_ = 1;
    uint64_t revision_ = 0;
    uint64_t savedState_ = 0;
};

}  // namespace pt::editor
