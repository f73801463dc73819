#pragma once
// The window's side of the pixel inspector: a pixel clicked (or hovered with Shift) on the image,
// or given by its column and row (Render ▸ Inspect pixel), shown in the inspector's window (made on
// first use), and that pixel's ray tree drawn over the image, to the depth chosen (the inspector's
// slider, View ▸ Ray tree depth), until the image is of another render.
#include <cstdint>
#include <functional>
#include <memory>

#include "inspect_action.h"

namespace whitted::viewer {

class ImageView;
class InspectorWindow;
class RenderController;

class PixelInspection {
public:
    PixelInspection(const RenderController& controller, ImageView& view);
    ~PixelInspection();
    PixelInspection(const PixelInspection&) = delete;
    PixelInspection& operator=(const PixelInspection&) = delete;

    // The report of image pixel (x, y) of the image shown (row 0 at the top), and its ray tree.
    void inspect(int x, int y);
    // Asks for X,Y, then inspects it.
    void ask();
    // Asks for the depth of the ray tree drawn (-1 hides it).
    void ask_depth();
    // The image shown is now (partly) of job `job`: a tree of another render's image no longer fits.
    void image_of_job(std::uint64_t job);

    std::function<void()> on_drawn;  // what is drawn over the image changed

private:
    InspectorWindow& window();
    void show(InspectorWindow& w);
    void draw();  // the tree of the last result over the image, as the controls say

    const RenderController& controller_;
    ImageView& view_;
    std::unique_ptr<InspectorWindow> window_;
    bool busy_ = false;  // an inspection is under way
    bool placed_ = false;  // the window was placed beside the main one
    InspectResult last_;
    std::uint64_t job_ = 0;  // the render whose image was inspected
    bool tree_on_ = true;
    int depth_ = -1;  // the deepest bounce drawn; -1: all of them
};

}  // namespace whitted::viewer
