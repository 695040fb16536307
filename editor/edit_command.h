#pragma once
// EditCommand: one undoable edit of a Document (STYLE.md rule 6: edits are commands that report
// what they changed). apply() and revert() each return the SceneDelta the backend must act on
// (the change bits and, where the command knows them, the materials, meshes or instances it
// touched), so an undo costs the same sync work as the edit it undoes.
#include <functional>
#include <memory>
#include <string>
#include <utility>

#include "editor/document.h"
#include "render/scene/scene_changes.h"

namespace pt::editor {

class EditCommand {
public:
    virtual ~EditCommand() = default;
    virtual std::string label() const = 0;  // for the Edit menu: "Undo <label>"
    virtual SceneDelta apply(Document& doc) = 0;
    virtual SceneDelta revert(Document& doc) = 0;
    // A slider drag produces one command per frame; while the drag lasts, each new command is
    // folded into the previous one (keeping the first "before" and the last "after"), so the
    // whole drag is one undo step. Only commands with the same non-empty mergeKey fold.
    virtual std::string mergeKey() const { return {}; }
    virtual void mergeFrom(EditCommand& later) { (void)later; }
};

// The common case: replace one value of the document, keeping the old one for undo.
// `assign` writes a value into the document (and whatever follows from it, e.g. instance
// transforms from an object transform); it must restore the document exactly when given
// `before` back.
template <class T>
class ValueCommand : public EditCommand {
public:
    using Assign = std::function<void(Document&, const T&)>;
    ValueCommand(std::string label, std::string mergeKey, SceneDelta changes, T before, T after,
                 Assign assign)
        : label_(std::move(label)),
          mergeKey_(std::move(mergeKey)),
          changes_(changes),
          before_(std::move(before)),
          after_(std::move(after)),
          assign_(std::move(assign)) {}

    std::string label() const override { return label_; }
    std::string mergeKey() const override { return mergeKey_; }
    SceneDelta apply(Document& doc) override {
        assign_(doc, after_);
        return changes_;
    }
    SceneDelta revert(Document& doc) override {
        assign_(doc, before_);
        return changes_;
    }
    void mergeFrom(EditCommand& later) override {
        after_ = static_cast<ValueCommand<T>&>(later).after_;
        changes_ |= static_cast<ValueCommand<T>&>(later).changes_;
    }
    const T& before() const { return before_; }
    const T& after() const { return after_; }

private:
    std::string label_, mergeKey_;
    SceneDelta changes_;
    T before_, after_;
    Assign assign_;
};

template <class T>
std::unique_ptr<EditCommand> makeValueCommand(std::string label, std::string mergeKey, SceneDelta changes,
                                              T before, T after, typename ValueCommand<T>::Assign assign) {
    return std::make_unique<ValueCommand<T>>(std::move(label), std::move(mergeKey), changes,
                                             std::move(before), std::move(after), std::move(assign));
}

}  // namespace pt::editor
