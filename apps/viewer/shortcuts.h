#pragma once
// Every key and mouse gesture of the viewer, for Help ▸ Keyboard shortcuts (the README lists the same).
namespace whitted::viewer {

struct Shortcut {
    const char* keys;
    const char* action;
};

inline constexpr Shortcut kShortcuts[] = {
    {"Left drag", "Orbit the camera about the focus point"},
    {"Middle drag, Shift+Left drag", "Pan the camera"},
    {"Wheel", "Dolly: move the camera towards / away from the focus point"},
    {"Ctrl+Wheel", "Field of view (zoom the lens)"},
    {"W A S D Q E", "Fly: forwards, left, backwards, right, down, up"},
    {"Home", "Camera back to the scene file's camera"},
    {"Right drag", "Move the picture in its area (does not change the camera)"},
    {"F / 1", "Fit the image to the area / show it 1:1"},
    {"+ / -", "Zoom the picture in / out (up to 16x, nearest neighbour)"},
    {"] / [ / \\", "Exposure up / down one stop / back to 0 (linear images)"},
    {"Left click, Shift+hover", "Inspect the pixel: its object's line, material, lights, colour parts, ray tree"},
    {"Ctrl+I", "Inspect a pixel given by its column and row"},
    {"Double-click a message", "Open the scene in $VISUAL or $EDITOR at the message's line"},
    {"Ctrl+Shift+C", "Copy the camera as a camera [ ... ] block"},
    {"Ctrl+Shift+S", "Save the camera into the scene file (asks first)"},
    {"Ctrl+O", "Open a scene (or drop a scene file on the window)"},
    {"Ctrl+R", "Reload the scene and render"},
    {"Ctrl+S", "Save the image as PNG, BMP, PPM or JPEG"},
    {"F5", "Render with the current settings"},
    {"Esc", "Stop rendering, keeping what is done"},
    {"Ctrl+T", "Scene time (velocity, angularrate)"},
    {"F1", "This list"},
    {"Ctrl+Q", "Quit"},
};

}  // namespace whitted::viewer
