#include "settings_bar.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>
#include <thread>
#include <utility>

#include <FL/Fl.H>
#include <FL/Fl_Button.H>
#include <FL/Fl_Check_Button.H>
#include <FL/Fl_Choice.H>
#include <FL/Fl_Menu_Bar.H>
#include <FL/Fl_Spinner.H>
#include <FL/Fl_Window.H>
#include <FL/fl_ask.H>

#include "session/render_settings.h"
#include "viewer_util.h"

namespace whitted::viewer {
namespace {

// Asks for a new value of a tool bar spinner (the Render menu reaches every control, also those
// a narrow window hides), then applies it as if typed there.
void ask_spinner(Fl_Spinner* s, const char* what) {
    char current[32];
    std::snprintf(current, sizeof current, "%d", int(s->value()));
    fl_message_title(what);  // a window named after its question (tests find it by name)
    const char* answer = fl_input("%s (%d to %d):", current, what, int(s->minimum()), int(s->maximum()));
    if (!answer) return;
    char* end = nullptr;
    const long v = std::strtol(answer, &end, 10);
    if (end == answer || *end || v < long(s->minimum()) || v > long(s->maximum())) {
        fl_alert("Not a whole number from %d to %d: %s", int(s->minimum()), int(s->maximum()), answer);
        return;
    }
    s->value(double(v));
    s->do_callback();
}

SettingsBar* bar(void* v) { return static_cast<SettingsBar*>(v); }

}  // namespace

SettingsBar* SettingsBar::active_ = nullptr;

// Made at their final sizes; layout() places them. Changing one renders again (after a moment, so
// that typing a number renders once).
SettingsBar::SettingsBar(const RenderJob& settings, bool fit, std::set<std::string> given)
    : base_(settings), given_(std::move(given)) {
    view_ = settings.integrator.mode == RenderMode::Path ? ViewTransform::Srgb : ViewTransform::Linear;
    const int h = 24;
    auto tool = [this](Fl_Widget* w, const char* id, int gap) {
        const Fl_Align a = w->align();
        int lw = 0, lh = 0;
        if ((a & FL_ALIGN_LEFT) && !(a & FL_ALIGN_INSIDE)) {  // a label drawn to its left needs room
            w->measure_label(lw, lh);
            lw += 5;
        }
        tools_.push_back({w, id, gap, lw, w->w(), w->h()});
    };
    render_ = new Fl_Button(0, 0, 70, h, "Render");
    render_->callback([](Fl_Widget*, void* v) {
        if (bar(v)->on_render) bar(v)->on_render();
    }, this);
    render_->tooltip("Render with these settings (F5)");
    tool(render_, "render", 0);
    stop_ = new Fl_Button(0, 0, 56, h, "Stop");
    stop_->callback([](Fl_Widget*, void* v) {
        if (bar(v)->on_stop) bar(v)->on_stop();
    }, this);
    stop_->tooltip("Stop rendering, keeping what is done (Esc)");
    tool(stop_, "stop", 4);
    auto spinner = [&](const char* id, const char* label, int gap, int sw, int lo, int hi, int value, const char* tip) {
        auto* s = new Fl_Spinner(0, 0, sw, h, label);
        s->type(FL_INT_INPUT);
        s->range(lo, hi);
        s->step(1);
        s->value(value);
        s->tooltip(tip);
        s->callback([](Fl_Widget* w, void* v) {  // the user's choice: a mode change leaves it alone
            SettingsBar* self = bar(v);
            for (const Tool& t : self->tools_)
                if (t.widget == w) self->given_.insert(std::string(t.id) == "depth" ? "max-depth" : t.id);
            self->changed();
        }, this);
        tool(s, id, gap);
        return s;
    };
    const RenderJob& st = settings;
    // Sized so that every tool fits the default 1000-pixel window.
    width_ = spinner("width", "Width", 12, 64, 1, 32768, st.width, "Image width in pixels");
    height_ = spinner("height", "Height", 8, 64, 1, 32768, st.height, "Image height in pixels");
    fit_ = new Fl_Check_Button(0, 0, 88, h, "Fit window");
    fit_->value(fit);
    fit_->tooltip("Render at the size of the image area");
    fit_->callback([](Fl_Widget* w, void* v) {
        SettingsBar* self = bar(v);
        bool on = static_cast<Fl_Check_Button*>(w)->value();
        if (on) self->width_->deactivate(), self->height_->deactivate();
        else self->width_->activate(), self->height_->activate();
        self->changed();
    }, this);
    if (fit) width_->deactivate(), height_->deactivate();
    tool(fit_, "fit", 8);
    depth_ = spinner("depth", "Depth", 8, 46, 0, 1000, st.integrator.max_depth,
                     "Recursion limit for reflection and refraction (the camera ray is depth 0)");
    mode_ = new Fl_Choice(0, 0, 80, h, "Mode");
    for (const char* md : kModes) mode_->add(md);
    mode_->value(int(st.integrator.mode));
    mode_->tooltip("whitted: the lab's lighting; raycast: unlit colour; normals, depth: debugging views; path: "
                   "physically based path tracing (set SPP to 64 or more)");
    mode_->callback([](Fl_Widget*, void* v) {
        bar(v)->apply_mode_defaults();
        bar(v)->changed();
    }, this);
    tool(mode_, "mode", 8);
    aa_ = spinner("aa", "AA", 8, 40, 1, Sampler::kMaxAa, st.sampling.aa,
                  "Anti-aliasing: N x N rays per pixel, averaged (1 = one ray through the pixel centre)");
    spp_ = spinner("spp", "SPP", 8, 54, 1, Sampler::kMaxSpp, st.sampling.spp,
                   "Samples per pixel (per anti-aliasing cell) for soft shadows, depth of field and gloss: they "
                   "arrive in passes, the image refining as you watch; Stop keeps the passes done");
    const int hw = int(std::max(1u, std::thread::hardware_concurrency()));
    threads_ = spinner("threads", "Threads", 8, 46, 1, 1024, st.threads > 0 ? st.threads : hw, "Worker threads");
    active_ = this;
    Fl::event_dispatch(dispatch);
}

SettingsBar::~SettingsBar() {
    Fl::remove_timeout(settled_cb, this);
    if (active_ == this) {
        active_ = nullptr;
        Fl::event_dispatch(nullptr);
    }
}

bool SettingsBar::editing() const {
    const Fl_Widget* f = Fl::focus();
    for (const Fl_Spinner* s : {width_, height_, depth_, aa_, spp_, threads_})
        if (f && (f == s || f->parent() == s)) return true;
    return false;
}

// Every event passes here first (Fl::event_dispatch): a spinner's text field takes every printable
// key (a number field drops the ones it cannot use), so the view's keys would never reach the menus.
int SettingsBar::dispatch(int event, Fl_Window* window) {
    SettingsBar* self = active_;
    if (event == FL_KEYBOARD && self && self->focus_home_ && self->editing()) {
        const char* text = Fl::event_text();
        const bool plain = !(Fl::event_state() & (FL_CTRL | FL_ALT | FL_META)) && Fl::event_length() == 1;
        const bool enter = Fl::event_key() == FL_Enter || Fl::event_key() == FL_KP_Enter;
        if (plain && text[0] > ' ' && text[0] < 127 && !std::isdigit(static_cast<unsigned char>(text[0]))) {
            Fl::focus(self->focus_home_);  // a view key: the field is done (its number is taken as it leaves)
        } else if (enter) {
            const int used = Fl::handle_(event, window);  // the field takes its number
            Fl::focus(self->focus_home_);
            return used;
        }
    }
    return Fl::handle_(event, window);
}

void SettingsBar::add_menu_items(Fl_Menu_Bar& m) {
    m.add("&Render/&Width...", 0, [](Fl_Widget*, void* v) { ask_spinner(bar(v)->width_, "Image width"); }, this);
    m.add("&Render/&Height...", 0, [](Fl_Widget*, void* v) { ask_spinner(bar(v)->height_, "Image height"); }, this);
    m.add("&Render/&Fit window", 0, [](Fl_Widget*, void* v) {
        SettingsBar* self = bar(v);
        self->fit_->value(!self->fit_->value());
        self->fit_->do_callback();
    }, this);
    m.add("&Render/&Depth...", 0, [](Fl_Widget*, void* v) { ask_spinner(bar(v)->depth_, "Recursion depth"); }, this);
    for (int i = 0; i < int(std::size(kModes)); ++i)
        m.add((std::string("&Render/&Mode/") + kModes[i]).c_str(), 0, [](Fl_Widget* w, void* v) {
            SettingsBar* self = bar(v);
            const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
            for (int k = 0; k < int(std::size(kModes)); ++k)
                if (item && item->label() && std::string(item->label()) == kModes[k]) self->mode_->value(k);
            self->mode_->do_callback();
        }, this);
    m.add("&Render/&Anti-aliasing...", 0, [](Fl_Widget*, void* v) {
        ask_spinner(bar(v)->aa_, "Anti-aliasing N (N x N rays per pixel)");
    }, this);
    m.add("&Render/Samples &per pixel...", 0, [](Fl_Widget*, void* v) { ask_spinner(bar(v)->spp_, "Samples per pixel"); },
          this);
    m.add("&Render/T&hreads...", 0, [](Fl_Widget*, void* v) { ask_spinner(bar(v)->threads_, "Worker threads"); }, this,
          FL_MENU_DIVIDER);
    // The load options of the command line.
    m.add("&Render/AA thres&hold...", 0, [](Fl_Widget*, void* v) { bar(v)->ask_aa_threshold(); }, this,
          FL_MENU_DIVIDER);
    for (const ViewTransform view : {ViewTransform::Linear, ViewTransform::Srgb, ViewTransform::Filmic})
        m.add((std::string("&Render/&View transform/") + view_transform_name(view)).c_str(), 0,
              [](Fl_Widget* w, void* v) {
                  const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
                  if (!item || !item->label()) return;
                  if (const auto chosen = parse_view_transform(item->label())) bar(v)->set_view(*chosen);
              },
              this, FL_MENU_RADIO);
    menu_ = &m;
    show_view();
}

void SettingsBar::set_view(ViewTransform view) {
    given_.insert("view");
    view_ = view;
    show_view();
    if (on_view) on_view();
}

void SettingsBar::show_view() {
    if (!menu_) return;
    const std::string path = std::string("&Render/&View transform/") + view_transform_name(view_);
    if (Fl_Menu_Item* item = const_cast<Fl_Menu_Item*>(menu_->find_item(path.c_str()))) item->setonly();
}

void SettingsBar::apply_mode_defaults() {
    RenderSettings s;
    s.mode = kModes[std::max(0, mode_->value())];
    s.given = given_;
    whitted::apply_mode_defaults(s);  // the table's: path gets 64 samples and 64 bounces
    if (!s.is_given("spp")) spp_->value(s.spp);
    if (!s.is_given("max-depth")) depth_->value(s.max_depth);
    if (!s.is_given("view")) {
        view_ = view_transform(s);
        show_view();
        if (on_view) on_view();
    }
}

RenderJob SettingsBar::job(int area_w, int area_h) {
    RenderJob s = base_;
    if (fit_->value()) {
        s.width = std::max(1, area_w);
        s.height = std::max(1, area_h);
        width_->value(s.width);
        height_->value(s.height);
    } else {
        s.width = int(width_->value());
        s.height = int(height_->value());
    }
    s.integrator.max_depth = int(depth_->value());
    s.integrator.mode = RenderMode(std::max(0, mode_->value()));
    s.sampling.aa = int(aa_->value());
    s.sampling.spp = int(spp_->value());
    s.threads = int(threads_->value());
    return s;
}

RenderJob SettingsBar::shown() const {
    RenderJob s = base_;
    s.width = int(width_->value());
    s.height = int(height_->value());
    s.integrator.max_depth = int(depth_->value());
    s.integrator.mode = RenderMode(std::max(0, mode_->value()));
    s.sampling.aa = int(aa_->value());
    s.sampling.spp = int(spp_->value());
    s.threads = int(threads_->value());
    return s;
}

bool SettingsBar::fit() const { return fit_->value() != 0; }
int SettingsBar::threads() const { return int(threads_->value()); }

void SettingsBar::set_busy(bool busy) {
    if (busy) stop_->activate();
    else stop_->deactivate();
}

void SettingsBar::layout(int window_w) {
    const int y = kMenuH + 5, right = window_w - 6;
    int x = 6;
    for (const Tool& t : tools_) {
        x += t.gap + t.label_w;
        t.widget->resize(x, y, t.w, t.h);
        if (x + t.w <= right) t.widget->show();
        else t.widget->hide();
        x += t.w;
    }
}

void SettingsBar::describe(std::ostream& out, int wx, int wy) const {
    for (const Tool& t : tools_) {
        const Fl_Widget* tw = t.widget;
        out << "tool " << t.id << " " << wx + tw->x() - t.label_w << " " << wy + tw->y() << " " << t.label_w + tw->w()
            << " " << tw->h() << " " << (tw->visible() ? "shown" : "hidden") << "\n";
    }
    const std::pair<const char*, const Fl_Spinner*> spinners[] = {{"width", width_}, {"height", height_},
                                                                   {"depth", depth_}, {"aa", aa_},
                                                                   {"spp", spp_},     {"threads", threads_}};
    for (const auto& [id, sp] : spinners) out << "setting " << id << " " << int(sp->value()) << "\n";
    out << "setting fit " << int(fit_->value()) << "\nsetting mode " << kModes[std::max(0, mode_->value())] << "\n";
}

void SettingsBar::changed_cb(Fl_Widget*, void* self) { bar(self)->changed(); }

// A setting changed: render again once the user has stopped typing or clicking.
void SettingsBar::changed() {
    Fl::remove_timeout(settled_cb, this);
    Fl::add_timeout(0.4, settled_cb, this);
}

// The change is applied: a field being typed into is done (the keys are the view's again).
void SettingsBar::settled_cb(void* self) {
    SettingsBar* b = bar(self);
    if (b->focus_home_ && b->editing()) Fl::focus(b->focus_home_);
    if (b->on_change) b->on_change();
}

// Render ▸ AA threshold (--aa-threshold): adaptive anti-aliasing, 0 = every pixel.
void SettingsBar::ask_aa_threshold() {
    char current[32];
    std::snprintf(current, sizeof current, "%g", double(base_.sampling.aa_threshold));
    const char* answer = fl_input("Adaptive anti-aliasing threshold, 0 to 1 (0: every pixel gets AA x AA rays; "
                                  "takes effect with AA > 1 and SPP 1):", current);
    if (!answer) return;
    char* end = nullptr;
    const float t = std::strtof(answer, &end);
    if (end == answer || *end || !std::isfinite(t) || t < 0.0f || t > 1.0f) {
        fl_alert("Not a number from 0 to 1: %s", answer);
        return;
    }
    base_.sampling.aa_threshold = t;
    if (on_render) on_render();
}

}  // namespace whitted::viewer
