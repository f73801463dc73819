#pragma once
// The camera of a viewing session: the scene file's camera as written (once a load got that far),
// and the camera the user moved to on the image (drag, wheel, fly keys), until Home goes back to the
// file's. Display-free: the window turns gestures into these calls and renders what current() says.
#include <optional>
#include <string>

#include "camera_text.h"
#include "description/scene_description.h"
#include "render/render_job.h"

namespace whitted::viewer {

class CameraSession {
public:
    // The camera on screen: the moved one, else the file's; none before a load got that far.
    std::optional<CameraDesc> current() const;
    bool moved() const { return camera_.has_value(); }

    // Another scene: its own camera (nothing moved, nothing known).
    void reset();
    // The file's camera as written, of a load that got that far (Home and the first move start there).
    void file_loaded(const CameraDesc& file_camera) { file_camera_ = file_camera; }

    // A drag's displacement since its press: the camera turns (orbit, screen pixels) or slides (pan,
    // image pixels of an image `image_height` rows high) from where it was at the press; `end` = the
    // button is released. False (and nothing changes) when no camera is known yet.
    bool orbit_drag(float dx, float dy, bool end);
    bool pan_drag(float dx, float dy, int image_height, bool end);
    // Wheel clicks: dolly, or (fov) the field of view. A fly key: w a s d q e.
    bool wheel(int steps, bool fov);
    bool fly(char key);
    // Back to the file's camera (the very image of the file). False when it was not moved.
    bool home();

    // The render job's camera: the moved one; the job's own (the file's) when not moved.
    void apply(RenderJob& job) const;

    // The camera on screen written into the scene file (camera_text.h): first planned (the block
    // that will be written, to ask about), then done, if the file has not changed meanwhile. The
    // file's camera is then this one. "" or the error (the file and the session unchanged).
    CameraSave plan_save(const std::string& scene_path) const;
    std::string save(const CameraSave& plan);

private:
    bool begin_drag();

    std::optional<CameraDesc> camera_;       // moved by the user; none = the file's
    std::optional<CameraDesc> file_camera_;  // of the last load that got that far
    CameraDesc drag_start_;                  // the camera when the current drag began
    bool in_drag_ = false;
};

}  // namespace whitted::viewer
