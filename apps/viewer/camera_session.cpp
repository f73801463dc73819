#include "camera_session.h"

#include <algorithm>

#include "camera_navigation.h"
#include "flatten/flatten.h"

namespace whitted::viewer {

std::optional<CameraDesc> CameraSession::current() const {
    if (camera_) return camera_;
    return file_camera_;
}

void CameraSession::reset() {
    camera_.reset();
    file_camera_.reset();
    in_drag_ = false;
}

bool CameraSession::begin_drag() {
    if (in_drag_) return true;
    const std::optional<CameraDesc> c = current();
    if (!c) return false;  // nothing loaded yet
    drag_start_ = navigable(*c);
    in_drag_ = true;
    return true;
}

bool CameraSession::orbit_drag(float dx, float dy, bool end) {
    if (!begin_drag()) return false;
    camera_ = orbit(drag_start_, dx, dy);
    if (end) in_drag_ = false;
    return true;
}

bool CameraSession::pan_drag(float dx, float dy, int image_height, bool end) {
    if (!begin_drag()) return false;
    camera_ = pan(drag_start_, dx, dy, std::max(1, image_height));
    if (end) in_drag_ = false;
    return true;
}

bool CameraSession::wheel(int steps, bool fov) {
    const std::optional<CameraDesc> c = current();
    if (!c) return false;
    camera_ = fov ? change_fov(navigable(*c), float(steps)) : dolly(navigable(*c), float(steps));
    return true;
}

bool CameraSession::fly(char key) {
    const std::optional<CameraDesc> c = current();
    if (!c) return false;
    camera_ = whitted::viewer::fly(navigable(*c), key);
    return true;
}

bool CameraSession::home() {
    if (!camera_) return false;
    camera_.reset();  // the file's camera: the very image of the file
    return true;
}

void CameraSession::apply(RenderJob& job) const {
    if (camera_) job.camera = make_camera(*camera_);  // the view the user moved to stays
}

CameraSave CameraSession::plan_save(const std::string& scene_path) const {
    const std::optional<CameraDesc> cam = current();
    if (!cam) {
        CameraSave none;
        none.error = "no camera to save: open a scene that loads";
        return none;
    }
    return plan_camera_save(scene_path, *cam);
}

std::string CameraSession::save(const CameraSave& plan) {
    const std::string err = commit_camera_save(plan);
    if (err.empty()) camera_.reset();  // the file's camera is this one now
    return err;
}

}  // namespace whitted::viewer
