#pragma once
// Moving the camera with the mouse and keys, as in Blender's viewport: orbit about the focus point,
// pan, dolly, field of view, fly. Display-free: each function maps a camera and a gesture (in
// pixels of the image, or wheel steps) to a new camera. The camera is a CameraDesc (eye, focus, up,
// angle: what the file says), so that the camera on screen can be written back into the file as
// text and give the very same image (make_camera of the same numbers).
#include "description/scene_description.h"

namespace whitted::viewer {

// The file's camera as one that looks at a point: a `look` camera gets the point on its view line
// nearest the world origin (or one unit ahead if the origin is behind it) as its focus.
CameraDesc navigable(const CameraDesc& file);

// Distance from the eye to the focus point.
float focus_distance(const CameraDesc& c);

// Turntable orbit about the focus point: dx pixels turn about `up` (the file's up stays the world's
// up), dy pixels tilt about the camera's right axis; 0.25 degree per pixel, the tilt stopping 1 degree
// short of looking straight along `up` (which the format forbids). The distance to the focus is kept.
CameraDesc orbit(const CameraDesc& c, float dx, float dy);
inline constexpr float kOrbitDegreesPerPixel = 0.25f;

// Pan: eye and focus move in the image plane so that points at the focus distance follow the mouse
// (dx to the right, dy down, in pixels of an image `image_height` pixels tall).
CameraDesc pan(const CameraDesc& c, float dx, float dy, int image_height);

// Dolly: each step (wheel click; positive = towards the focus) takes the eye 1/10 of the way
// towards the focus point (or away); the eye never reaches the focus.
CameraDesc dolly(const CameraDesc& c, float steps);

// Field of view: each step (positive = zoom in) narrows the angle by a factor 1.1, kept in [1, 170].
CameraDesc change_fov(const CameraDesc& c, float steps);

// Fly keys: W/S forwards/backwards, A/D left/right, Q/E down/up (along the camera's own axes);
// eye and focus move together by `fraction` of the focus distance. Other keys: unchanged.
CameraDesc fly(const CameraDesc& c, char key, float fraction = 0.1f);

}  // namespace whitted::viewer
