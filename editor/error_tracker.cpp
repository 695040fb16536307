#include "editor/error_tracker.h"

namespace pt::editor {

void ErrorTracker::load(const std::string& path) {
    setReference(std::make_shared<ReferenceImage>(loadReferenceImage(path)));
}

void ErrorTracker::setReference(std::shared_ptr<const ReferenceImage> reference) {
    std::lock_guard<std::mutex> lock(mutex_);
    reference_ = std::move(reference);
    curve_.clear();
    problem_.clear();
}

void ErrorTracker::clear() { setReference(nullptr); }

std::shared_ptr<const ReferenceImage> ErrorTracker::reference() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return reference_;
}

void ErrorTracker::restart() {
    std::lock_guard<std::mutex> lock(mutex_);
    curve_.clear();
}

bool ErrorTracker::due(double seconds, uint32_t spp, uint32_t width, uint32_t height) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!reference_ || spp == 0) return false;
    if (reference_->width != width || reference_->height != height) {
        problem_ = "the reference is " + std::to_string(reference_->width) + "x" +
                   std::to_string(reference_->height) + ", the render " + std::to_string(width) + "x" +
                   std::to_string(height);
        curve_.clear();
        return false;
    }
    problem_.clear();
    if (!curve_.empty() && (spp < curve_.back().spp || seconds < curve_.back().seconds)) curve_.clear();
    return curve_.empty() || seconds >= curve_.back().seconds * kSpacing;
}

void ErrorTracker::add(double seconds, uint32_t spp, const std::vector<float>& beauty) {
    std::shared_ptr<const ReferenceImage> reference = this->reference();
    if (!reference || beauty.size() != reference->rgba.size()) return;
    // Measured outside the lock: the UI thread keeps reading the curve meanwhile.
    const ImageError error = imageError(beauty, reference->rgba);
    std::lock_guard<std::mutex> lock(mutex_);
    if (reference_ != reference) return;  // replaced while measuring
    curve_.push_back({seconds, spp, error});
}

std::vector<ErrorPoint> ErrorTracker::curve() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return curve_;
}

std::string ErrorTracker::problem() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return problem_;
}

}  // namespace pt::editor
