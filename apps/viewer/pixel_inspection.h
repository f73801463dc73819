#pragma once
// The window's side of the pixel inspector: a pixel clicked (or hovered with Shift) on the image,
// or given by its column and row (Render ▸ Inspect pixel), shown in the inspector's window, made
// on first use.
#include <memory>

namespace whitted::viewer {

class InspectorWindow;
class RenderController;

class PixelInspection {
public:
    explicit PixelInspection(const RenderController& controller);
    ~PixelInspection();
    PixelInspection(const PixelInspection&) = delete;
    PixelInspection& operator=(const PixelInspection&) = delete;

    // The report of image pixel (x, y) of the image shown (row 0 at the top).
    void inspect(int x, int y);
    // Asks for X,Y, then inspects it.
    void ask();

private:
    InspectorWindow& window();

    const RenderController& controller_;
    std::unique_ptr<InspectorWindow> window_;
    bool busy_ = false;  // an inspection is under way
};

}  // namespace whitted::viewer
