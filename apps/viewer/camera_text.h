#pragma once
// The camera back into the scene text: a `camera [ … ]` block for the clipboard, and the scene file
// with its camera block replaced (every other byte kept). Display-free and unit-tested.
#include <string>
#include <string_view>

#include "description/scene_description.h"

namespace whitted::viewer {

// The shortest decimal text that reads back (as the parser reads numbers: double, then float) as
// exactly `value`.
std::string format_number(float value);

// `camera [ eye x y z focus x y z up x y z angle a ]`, with `near-far` when not the defaults, and
// `aperture`/`focaldistance` for a lens (also for a pinhole when `state_pinhole`, to override what an
// earlier block set). Read back, it gives the same camera, hence the same image.
std::string camera_block(const CameraDesc& camera, bool state_pinhole = false);

// Where the camera blocks are: byte offsets of the `camera` keyword and one past its closing `]`.
struct BlockSpan {
    std::size_t begin = 0, end = 0;
};

struct CameraReplacement {
    std::string text;   // the new file contents (when error is empty)
    std::string block;  // the camera block in it as written there (what to show the user)
    std::string error;  // e.g. a camera block that is never closed
    int blocks = 0;     // camera blocks found in the old text
};

// The scene text with its camera made `camera`, every byte outside the last camera block kept.
// That block is edited in place: the numbers of its keywords that change are rewritten, and the
// keywords it lacks are added before its `]` only where the camera would otherwise differ (the
// format merges several blocks keyword by keyword, later ones winning: scene-format.md §5, so
// earlier blocks count); its comments and layout stay. No camera block: a new one goes at the top.
CameraReplacement replace_camera_block(std::string_view text, const CameraDesc& camera);

// A save of the camera into a scene file, planned on the file's text as it is now.
struct CameraSave {
    std::string path, old_text;
    CameraReplacement replacement;
    std::string error;  // the file could not be read, or its text not made sense of
};
CameraSave plan_camera_save(const std::string& path, const CameraDesc& camera);

// Writes a planned save if the file still holds the text it was planned on, atomically: the new
// text goes to a temporary file in the same folder, which is renamed over the old one (keeping its
// permissions, owner and group where allowed). Through a symbolic link, the file it leads to is
// replaced (the link stays); a file with several hard links is rewritten in place once the new text
// is safe in the temporary file, so that every name sees it. Returns "" or an error message; on
// error the file is untouched (in place: the message names the temporary file holding the new text).
std::string commit_camera_save(const CameraSave& plan);

// Both at once.
std::string save_camera_into_file(const std::string& path, const CameraDesc& camera);

}  // namespace whitted::viewer
