#include "preferences.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <FL/Fl_Menu_Bar.H>
#include <FL/Fl_Preferences.H>

namespace whitted::viewer {
namespace {

constexpr int kRecentMax = 10;

Fl_Preferences user_preferences() { return Fl_Preferences(Fl_Preferences::USER, "whitted", "whitted-view"); }

}  // namespace

Preferences::Preferences() {
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
    if (ww >= 520 && wh >= 300 && ww <= 16384 && wh <= 16384) window_size_ = {ww, wh};
}

void Preferences::recall_settings(RenderJob& s, bool& fit) const {
    Fl_Preferences prefs = user_preferences();
    Fl_Preferences st(prefs, "settings");
    int v = 0;
    st.get("width", v, s.width), s.width = std::clamp(v, 1, 32768);
    st.get("height", v, s.height), s.height = std::clamp(v, 1, 32768);
    st.get("depth", v, s.integrator.max_depth), s.integrator.max_depth = std::clamp(v, 0, 1000);
    st.get("aa", v, s.sampling.aa), s.sampling.aa = std::clamp(v, 1, Sampler::kMaxAa);
    st.get("spp", v, s.sampling.spp), s.sampling.spp = std::clamp(v, 1, Sampler::kMaxSpp);
    st.get("mode", v, int(s.integrator.mode)), s.integrator.mode = RenderMode(std::clamp(v, 0, 4));
    st.get("fit", v, int(fit)), fit = v != 0;
    if (s.sampling.spp > 1) s.sampling.aa_threshold = 0.0f;
}

void Preferences::save(int window_w, int window_h, const RenderJob* settings, bool fit) const {
    Fl_Preferences prefs = user_preferences();
    Fl_Preferences recent(prefs, "recent");
    recent.deleteAllEntries();
    for (std::size_t i = 0; i < recent_.size(); ++i) recent.set(std::to_string(i).c_str(), recent_[i].c_str());
    Fl_Preferences window(prefs, "window");
    window.set("width", window_w);
    window.set("height", window_h);
    if (settings) {
        const RenderJob& s = *settings;
        Fl_Preferences st(prefs, "settings");
        st.set("width", s.width);
        st.set("height", s.height);
        st.set("depth", s.integrator.max_depth);
        st.set("aa", s.sampling.aa);
        st.set("spp", s.sampling.spp);
        st.set("mode", int(s.integrator.mode));
        st.set("fit", int(fit));
    }
    prefs.flush();
}

void Preferences::add_recent(const std::string& path) {
    std::error_code ec;
    const std::string abs = std::filesystem::absolute(path, ec).lexically_normal().string();
    const std::string& p = ec ? path : abs;
    recent_.erase(std::remove(recent_.begin(), recent_.end(), p), recent_.end());
    recent_.insert(recent_.begin(), p);
    if (recent_.size() > std::size_t(kRecentMax)) recent_.resize(kRecentMax);
}

void Preferences::fill_recent_menu(Fl_Menu_Bar& menu, const char* submenu,
                                   std::function<void(const std::string&)> open) {
    open_recent_ = std::move(open);
    recent_submenu_ = submenu;
    const int at = menu.find_index(submenu);
    if (at < 0) return;
    menu.clear_submenu(at);
    if (recent_.empty()) {
        menu.add((recent_submenu_ + "/(none)").c_str(), 0, nullptr, nullptr, FL_MENU_INACTIVE);
        return;
    }
    for (const std::string& path : recent_) {
        // '/' would make a submenu and '&' a shortcut: escaped for the menu label.
        std::string label;
        for (char c : path) {
            if (c == '/' || c == '\\' || c == '&' || c == '_') label += '\\';
            label += c;
        }
        // The item's place in the submenu says which path it is (its user data is this object).
        menu.add((recent_submenu_ + "/" + label).c_str(), 0, [](Fl_Widget* w, void* v) {
            auto* self = static_cast<Preferences*>(v);
            auto* m = static_cast<Fl_Menu_Bar*>(w);
            const int first = m->find_index(self->recent_submenu_.c_str()) + 1, i = m->value() - first;
            if (first > 0 && i >= 0 && i < int(self->recent_.size()) && self->open_recent_)
                self->open_recent_(std::string(self->recent_[std::size_t(i)]));
        }, this);
    }
}

}  // namespace whitted::viewer
