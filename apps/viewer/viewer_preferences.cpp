// What the viewer remembers between runs (FLTK's Fl_Preferences, in ~/.fltk/whitted/): the recent
// scenes, the window size and the render settings.
#include <algorithm>
#include <filesystem>

#include <FL/Fl_Check_Button.H>
#include <FL/Fl_Choice.H>
#include <FL/Fl_Menu_Bar.H>
#include <FL/Fl_Preferences.H>
#include <FL/Fl_Spinner.H>

#include "viewer_window.h"

namespace whitted::viewer {
namespace {

constexpr int kRecentMax = 10;

Fl_Preferences user_preferences() { return Fl_Preferences(Fl_Preferences::USER, "whitted", "whitted-view"); }

}  // namespace

// Before the widgets are made: they start from what was remembered, unless the command line said.
void ViewerWindow::load_preferences() {
    Fl_Preferences prefs = user_preferences();
    Fl_Preferences recent(prefs, "recent");
    for (int i = 0; i < std::min(recent.entries(), kRecentMax); ++i) {
        char* path = nullptr;
        recent.get(std::to_string(i).c_str(), path, "");
        if (path && *path && std::find(recent_.begin(), recent_.end(), path) == recent_.end()) recent_.push_back(path);
        if (path) free(path);
    }
    Fl_Preferences window(prefs, "window");
    int ww = 0, wh = 0;
    window.get("width", ww, 0);
    window.get("height", wh, 0);
    if (!options_.window_size_given && ww >= 520 && wh >= 300 && ww <= 16384 && wh <= 16384) size(ww, wh);
    if (!options_.settings_given) {
        Fl_Preferences st(prefs, "settings");
        RenderJob& s = options_.settings;
        int v = 0;
        st.get("width", v, s.width), s.width = std::clamp(v, 1, 32768);
        st.get("height", v, s.height), s.height = std::clamp(v, 1, 32768);
        st.get("depth", v, s.integrator.max_depth), s.integrator.max_depth = std::clamp(v, 0, 1000);
        st.get("aa", v, s.sampling.aa), s.sampling.aa = std::clamp(v, 1, Sampler::kMaxAa);
        st.get("spp", v, s.sampling.spp), s.sampling.spp = std::clamp(v, 1, Sampler::kMaxSpp);
        st.get("mode", v, int(s.integrator.mode)), s.integrator.mode = RenderMode(std::clamp(v, 0, 4));
        st.get("fit", v, int(options_.fit_window)), options_.fit_window = v != 0;
        if (s.sampling.spp > 1) s.sampling.aa_threshold = 0.0f;
    }
}

void ViewerWindow::remember() {
    Fl_Preferences prefs = user_preferences();
    Fl_Preferences recent(prefs, "recent");
    recent.deleteAllEntries();
    for (std::size_t i = 0; i < recent_.size(); ++i) recent.set(std::to_string(i).c_str(), recent_[i].c_str());
    Fl_Preferences window(prefs, "window");
    window.set("width", w());
    window.set("height", h());
    Fl_Preferences st(prefs, "settings");
    st.set("width", int(width_->value()));
    st.set("height", int(height_->value()));
    st.set("depth", int(depth_->value()));
    st.set("aa", int(aa_->value()));
    st.set("spp", int(spp_->value()));
    st.set("mode", std::max(0, mode_->value()));
    st.set("fit", int(fit_->value()));
    prefs.flush();
}

// Most recent first, absolute, no duplicates, at most ten.
void ViewerWindow::add_recent(const std::string& path) {
    std::error_code ec;
    const std::string abs = std::filesystem::absolute(path, ec).lexically_normal().string();
    const std::string& p = ec ? path : abs;
    recent_.erase(std::remove(recent_.begin(), recent_.end(), p), recent_.end());
    recent_.insert(recent_.begin(), p);
    if (recent_.size() > std::size_t(kRecentMax)) recent_.resize(kRecentMax);
    if (menu_) rebuild_recent_menu();
    remember();
}

}  // namespace whitted::viewer
