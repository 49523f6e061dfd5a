// The viewer's window, input and main loop (viewer.h).

#include "viewer/viewer.h"

// OpenGL from gl_api.h (glvnd's libOpenGL), not GLFW's choice of header.
#include "gl/gl_api.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <string>
#include <thread>

#include "gl/gl_objects.h"
#include "gl/gl_program.h"
#include "viewer/camera_controls.h"
#include "viewer/panel_layout.h"
#include "viewer/render_worker.h"
#include "viewer/transfer_editing.h"
#include "viewer/viewer_panel.h"
#include "viewer/volume_panel.h"
#include "vissort/frame_driver.h"
#include "vissort/image.h"

namespace vissort::viewer {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kPlotted = 120; // frame times in the panel's plot

// The last GLFW error, for the one-line messages.
std::string g_glfw_error;
void recordGlfwError(int, const char* description) {
    g_glfw_error = description;
}

// Shows the renderer's image one pixel per pixel, from the top-left corner of the part of the
// window right of the panel (`left` pixels in): the same bytes `vissort render` writes (no
// filtering, no scaling); a grey margin where the window is larger than the image (between a
// resize and the frame at the new size).
constexpr const char* kBlitVertex = R"(#version 330 core
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";
constexpr const char* kBlitFragment = R"(#version 330 core
uniform sampler2D image;
uniform int window_height;
uniform int left;
out vec4 colour;
void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    pixel.y = window_height - 1 - pixel.y; // the image's rows run from the top
    pixel.x -= left;
    ivec2 size = textureSize(image, 0);
    if (pixel.x < 0 || pixel.x >= size.x || pixel.y >= size.y)
        colour = vec4(0.5, 0.5, 0.5, 1.0);
    else
        colour = texelFetch(image, pixel, 0);
}
)";

class Viewer {
public:
    /// grid: null for a scene's window; else the grid whose boundary scene is.
    Viewer(const Scene& scene, const TetGrid* grid, const ViewerSettings& settings);
    ~Viewer();
    Status open();
    Result<ViewerSummary> run();

private:
    // The panel for the window's current size; width 0 when hidden (Tab, --hide-ui).
    PanelLayout layout() const;
    // Input, from GLFW's callbacks or the script.
    void onKey(const std::string& name);
    // A grid's keys; false for those a grid's window does not take.
    bool onVolumeKey(const std::string& name);
    void onDrag(int button, double dx, double dy);
    void onWheel(double steps);
    Status onResize(uint32_t width, uint32_t height);
    void applyScript(int frame);
    // The camera moved by the user: it no longer follows the path.
    void moveCamera(const CameraSpec& camera);
    CameraSpec currentCamera() const;
    RenderRequest request() const;
    void show(RenderedFrame frame);
    void drawWindow();
    Status saveScreenshot(const std::string& path);
    static Viewer& of(GLFWwindow* window) {
        return *static_cast<Viewer*>(glfwGetWindowUserPointer(window));
    }

    const Scene& scene_;
    const TetGrid* grid_;
    ViewerSettings settings_;
    RenderSettings render_;
    std::optional<VolumeView> volume_; // a grid's settings, edited in the panel
    std::optional<GridFacts> grid_facts_;
    Overlays overlays_;
    GLFWwindow* window_ = nullptr;
    bool imgui_ = false;
    std::unique_ptr<RenderWorker> worker_;
    // The window context's objects; released before the window (the destructor).
    detail::GlObject<detail::DeleteTexture> texture_;
    detail::GlObject<detail::DeleteVertexArray> vertex_array_;
    detail::GlProgram blit_;
    GLint image_uniform_ = -1, height_uniform_ = -1, left_uniform_ = -1;

    CameraSpec camera_;          // the user's camera, once moved
    bool following_path_ = true; // the path's camera (the start camera on a static path)
    Bounds first_bounds_;        // the path turns about the first frame's bounds
    double radius_ = 1;          // the first frame's bounding sphere
    int frame_ = 0;              // the animation frame rendered next
    bool playing_ = true;
    bool animated_ = false; // a dynamic scene or a moving path: frames differ
    bool dirty_ = true;     // something changed since the frame on screen
    bool help_ = false;
    bool panel_shown_ = true; // Tab, or the panel's button, hides and shows it
    bool quit_ = false;
    std::string pending_error_;
    std::size_t next_event_ = 0;
    int screenshot_count_ = 0;
    bool screenshot_asked_ = false; // P: saved once the window is drawn, before it is shown
    // Dragging: the button held and the cursor's last position.
    int drag_button_ = -1;
    double cursor_x_ = 0, cursor_y_ = 0;

    std::optional<RenderedFrame> shown_;
    std::vector<float> frame_ms_; // the last kPlotted frames, for the panel's plot
    std::vector<double> all_ms_;
    std::deque<Clock::time_point> frame_times_;
    std::optional<DepthComplexity> complexity_;
    ViewerSummary summary_;
};

Viewer::Viewer(const Scene& scene, const TetGrid* grid, const ViewerSettings& settings)
    : scene_(scene), grid_(grid), settings_(settings), render_(settings.render),
      volume_(settings.volume), overlays_(settings.overlays), camera_(settings.camera) {
    if (grid_ != nullptr)
        grid_facts_ = describeGrid(*grid_);
    FrameDriver driver(scene_);
    driver.seek(0);
    first_bounds_ = driver.positions().bounds();
    radius_ = std::max(first_bounds_.radius(), 1e-9);
    animated_ = scene_.isDynamic() || settings_.path != CameraPath::fixed;
}

Viewer::~Viewer() {
    worker_.reset(); // the render thread and its context first
    if (window_ != nullptr) {
        glfwMakeContextCurrent(window_);
        blit_ = {};
        texture_ = {};
        vertex_array_ = {};
        if (imgui_) {
            ImGui_ImplOpenGL3_Shutdown();
            ImGui_ImplGlfw_Shutdown();
            ImGui::DestroyContext();
        }
        glfwDestroyWindow(window_);
    }
    glfwTerminate();
}

Status Viewer::open() {
    glfwSetErrorCallback(recordGlfwError);
    if (!glfwInit())
        return Status::failure("view needs a display (X11 or Wayland) and none could be opened (" +
                               g_glfw_error +
                               "): run it under xvfb-run, or write images with vissort render");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_FALSE);
    window_ = glfwCreateWindow(int(settings_.width), int(settings_.height), settings_.title.c_str(),
                               nullptr, nullptr);
    if (window_ == nullptr)
        return Status::failure("cannot open a window with OpenGL 3.3: " + g_glfw_error);
    glfwSetWindowUserPointer(window_, this);
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(settings_.frames > 0 ? 0 : 1);

    // Ours first: ImGui's backend chains to them.
    glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int, int action, int) {
        if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard)
            return;
        // The names scripts use (input_script.h); GLFW's codes for letters and digits are their
        // ASCII characters.
        if (key == GLFW_KEY_SPACE)
            of(window).onKey("SPACE");
        else if (key == GLFW_KEY_ESCAPE)
            of(window).onKey("ESCAPE");
        else if (key == GLFW_KEY_TAB)
            of(window).onKey("TAB");
        else if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) ||
                 (key >= GLFW_KEY_1 && key <= GLFW_KEY_7) || key == GLFW_KEY_LEFT_BRACKET ||
                 key == GLFW_KEY_RIGHT_BRACKET)
            of(window).onKey(std::string(1, char(key)));
    });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* window, int button, int action, int) {
        Viewer& viewer = of(window);
        if (action == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse && button <= 2) {
            viewer.drag_button_ = button;
            glfwGetCursorPos(window, &viewer.cursor_x_, &viewer.cursor_y_);
        } else if (action == GLFW_RELEASE && button == viewer.drag_button_) {
            viewer.drag_button_ = -1;
        }
    });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* window, double x, double y) {
        Viewer& viewer = of(window);
        if (viewer.drag_button_ < 0)
            return;
        viewer.onDrag(viewer.drag_button_, x - viewer.cursor_x_, y - viewer.cursor_y_);
        viewer.cursor_x_ = x;
        viewer.cursor_y_ = y;
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* window, double, double y) {
        if (!ImGui::GetIO().WantCaptureMouse)
            of(window).onWheel(y);
    });
    glfwSetFramebufferSizeCallback(window_,
                                   [](GLFWwindow* window, int, int) { of(window).dirty_ = true; });

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini written where the user runs it
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL3_Init("#version 330");
    imgui_ = true;

    try {
        blit_ = detail::linkProgram(kBlitVertex, kBlitFragment);
    } catch (const std::exception& error) {
        return Status::failure(std::string("the viewer's image program: ") + error.what());
    }
    image_uniform_ = glGetUniformLocation(blit_.get(), "image");
    height_uniform_ = glGetUniformLocation(blit_.get(), "window_height");
    left_uniform_ = glGetUniformLocation(blit_.get(), "left");
    GLuint name = 0;
    glGenVertexArrays(1, &name);
    vertex_array_ = detail::GlObject<detail::DeleteVertexArray>(name);
    glGenTextures(1, &name);
    texture_ = detail::GlObject<detail::DeleteTexture>(name);
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    worker_ = std::make_unique<RenderWorker>(scene_, grid_);
    return Status::ok();
}

PanelLayout Viewer::layout() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return panelLayout(uint32_t(std::max(width, 1)), uint32_t(std::max(height, 1)),
                       panel_shown_ && !settings_.hide_ui);
}

CameraSpec Viewer::currentCamera() const {
    if (!following_path_)
        return camera_;
    return cameraOnPath(settings_.camera, settings_.path, frame_, first_bounds_,
                        scene_.camera_path);
}

void Viewer::moveCamera(const CameraSpec& camera) {
    camera_ = camera;
    following_path_ = false;
    dirty_ = true;
}

bool Viewer::onVolumeKey(const std::string& name) {
    VolumeView& volume = *volume_;
    constexpr double kDensityStep = 1.5;
    if (name.size() == 1 && name[0] >= '1' && name[0] <= '7') {
        if (name[0] > '5')
            return true; // 6 and 7 are scene methods
        volume.method = kVolumeMethodNames[name[0] - '1'].value;
    } else if (name == "T") {
        volume.tf_name = nextTransferPreset(volume.tf_name);
        volume.settings.transfer = *loadTransferFunction(volume.tf_name).value;
    } else if (name == "[" || name == "]") {
        // Held within the panel slider's reach and far from 0 and infinity, which a held key
        // would otherwise reach (an infinite density is refused, and would end the window).
        volume.settings.density = std::clamp(
            volume.settings.density * (name == "]" ? kDensityStep : 1 / kDensityStep), 1e-6, 1e6);
    } else if (name == "X") {
        overlays_.error_map = !overlays_.error_map;
    } else {
        return name == "C" || name == "K"; // a scene's overlays: nothing to do for a grid
    }
    dirty_ = true;
    return true;
}

void Viewer::onKey(const std::string& name) {
    const double step = kFlyStepOfRadius * radius_;
    if (volume_ && onVolumeKey(name))
        return;
    if (name == "ESCAPE") {
        quit_ = true;
    } else if (name == "W") {
        moveCamera(fly(currentCamera(), 1, 0, 0, step));
    } else if (name == "S") {
        moveCamera(fly(currentCamera(), -1, 0, 0, step));
    } else if (name == "A") {
        moveCamera(fly(currentCamera(), 0, -1, 0, step));
    } else if (name == "D") {
        moveCamera(fly(currentCamera(), 0, 1, 0, step));
    } else if (name == "Q") {
        moveCamera(fly(currentCamera(), 0, 0, -1, step));
    } else if (name == "E") {
        moveCamera(fly(currentCamera(), 0, 0, 1, step));
    } else if (name == "F") {
        moveCamera(frameBounds(currentCamera(), first_bounds_));
    } else if (name == "R") {
        camera_ = settings_.camera;
        following_path_ = true;
        dirty_ = true;
    } else if (name == "SPACE") {
        playing_ = !playing_;
        dirty_ = true;
    } else if (name == "P") {
        screenshot_asked_ = true;
    } else if (name == "H") {
        help_ = !help_;
    } else if (name == "TAB") {
        panel_shown_ = !panel_shown_;
        dirty_ = true; // the scene's part of the window changed
    } else if (name == "C") {
        render_.colour_cycles = !render_.colour_cycles;
        dirty_ = true;
    } else if (name == "K") {
        overlays_.highlight_collisions = !overlays_.highlight_collisions;
        dirty_ = true;
    } else if (name == "X") {
        overlays_.error_map = !overlays_.error_map;
        dirty_ = true;
    } else if (name.size() == 1 && name[0] >= '1' && name[0] <= '7') {
        render_.method = kBlendMethodNames[name[0] - '1'].value;
        dirty_ = true;
    }
}

void Viewer::onDrag(int button, double dx, double dy) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    if (button == 0)
        moveCamera(orbit(currentCamera(), dx, dy));
    else
        moveCamera(pan(currentCamera(), dx, dy, double(std::max(height, 1))));
}

void Viewer::onWheel(double steps) {
    moveCamera(zoom(currentCamera(), steps, radius_ * 1e-3));
}

Status Viewer::onResize(uint32_t width, uint32_t height) {
    glfwSetWindowSize(window_, int(width), int(height));
    // A window manager (or none, under Xvfb) answers later: wait for the new size, briefly.
    const Clock::time_point give_up = Clock::now() + std::chrono::seconds(5);
    for (;;) {
        glfwPollEvents();
        int w = 0, h = 0;
        glfwGetFramebufferSize(window_, &w, &h);
        if (uint32_t(w) == width && uint32_t(h) == height)
            break;
        if (Clock::now() > give_up)
            return Status::failure("the window was not resized to " + std::to_string(width) + "x" +
                                   std::to_string(height) + " (it is " + std::to_string(w) + "x" +
                                   std::to_string(h) + ")");
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    dirty_ = true;
    return Status::ok();
}

void Viewer::applyScript(int frame) {
    const std::vector<ScriptEvent>& events = settings_.script;
    for (; next_event_ < events.size() && events[next_event_].frame <= frame; ++next_event_) {
        const ScriptEvent& event = events[next_event_];
        switch (event.kind) {
        case ScriptEvent::Kind::key:
            onKey(event.key);
            break;
        case ScriptEvent::Kind::drag:
            onDrag(event.button, event.x1 - event.x0, event.y1 - event.y0);
            break;
        case ScriptEvent::Kind::wheel:
            onWheel(event.steps);
            break;
        case ScriptEvent::Kind::resize:
            if (Status resized = onResize(event.width, event.height); !resized)
                pending_error_ = resized.error;
            break;
        }
    }
}

RenderRequest Viewer::request() const {
    RenderRequest request;
    request.settings = render_;
    request.volume = volume_;
    request.overlays = overlays_;
    request.camera = currentCamera();
    request.frame = frame_;
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    request.height = uint32_t(std::max(height, 1));
    request.width = sceneWidth(uint32_t(std::max(width, 1)), request.height,
                               panel_shown_ && !settings_.hide_ui);
    return request;
}

void Viewer::show(RenderedFrame frame) {
    if (!frame.error.empty()) {
        pending_error_ = frame.error;
        return;
    }
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, GLsizei(frame.request.width),
                 GLsizei(frame.request.height), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 frame.frame.rgba.data());
    const float ms = float(frame.frame.stats.total_ms);
    if (frame_ms_.size() == kPlotted)
        frame_ms_.erase(frame_ms_.begin());
    frame_ms_.push_back(ms);
    all_ms_.push_back(ms);
    const Clock::time_point now = Clock::now();
    frame_times_.push_back(now);
    while (frame_times_.size() > 2 && now - frame_times_.front() > std::chrono::seconds(2))
        frame_times_.pop_front();
    ++summary_.frames;
    summary_.camera = frame.request.camera;
    summary_.render = frame.request.settings;
    summary_.width = frame.request.width;
    summary_.height = frame.request.height;
    summary_.overlays = frame.request.overlays;
    summary_.colliding_pairs = frame.frame.colliding_pairs;
    summary_.difference = frame.frame.error;
    summary_.volume = frame.request.volume;
    summary_.volume_stats = frame.volume_stats;
    shown_ = std::move(frame);
    if (playing_ && animated_)
        ++frame_;
}

void Viewer::drawWindow() {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    glViewport(0, 0, width, height);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (shown_) {
        glUseProgram(blit_.get());
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, texture_.get());
        glUniform1i(image_uniform_, 0);
        glUniform1i(height_uniform_, height);
        glUniform1i(left_uniform_, int(layout().width));
        glBindVertexArray(vertex_array_.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glUseProgram(0);
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    const PanelLayout panel = layout();
    ImGui::GetIO().FontGlobalScale = panel.scale;
    ImGui::NewFrame();
    if (!settings_.hide_ui && !panel_shown_ && drawShowPanelButton())
        onKey("TAB");
    if (!settings_.hide_ui && panel_shown_) {
        PanelState state;
        state.layout = panel;
        state.scene = &scene_;
        state.last = shown_ ? &*shown_ : nullptr;
        state.frame_ms = frame_ms_;
        state.frame = frame_;
        state.playing = playing_;
        state.complexity = &complexity_;
        if (frame_times_.size() >= 2) {
            const double seconds =
                std::chrono::duration<double>(frame_times_.back() - frame_times_.front()).count();
            state.fps = seconds > 0 ? double(frame_times_.size() - 1) / seconds : 0;
        }
        state.grid_facts = grid_facts_ ? &*grid_facts_ : nullptr;
        const PanelActions actions = volume_ ? drawVolumePanel(state, *volume_, overlays_)
                                             : drawPanel(state, render_, overlays_);
        if (actions.settings_changed)
            dirty_ = true;
        if (actions.toggle_play)
            onKey("SPACE");
        if (actions.frame_scene)
            onKey("F");
        if (actions.reset_camera)
            onKey("R");
        if (actions.screenshot)
            onKey("P");
        if (actions.hide_panel)
            onKey("TAB");
        if (actions.measure_complexity) {
            FrameDriver driver(scene_);
            driver.seek(frame_);
            try {
                complexity_ = estimateDepthComplexity(
                    driver.positions(), currentCamera(), driver.positions().bounds(),
                    uint32_t(std::max(width - int(panel.width), 1)), uint32_t(height), 128);
            } catch (const std::exception& error) {
                pending_error_ = error.what();
            }
        }
    }
    if (!settings_.hide_ui && help_)
        drawHelpOverlay();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

Status Viewer::saveScreenshot(const std::string& path) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    std::vector<uint8_t> rows(std::size_t(width) * height * 4);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    std::vector<uint8_t> image(rows.size());
    const std::size_t stride = std::size_t(width) * 4;
    for (int y = 0; y < height; ++y) // OpenGL's rows run from the bottom
        std::copy_n(rows.data() + std::size_t(height - 1 - y) * stride, stride,
                    image.data() + std::size_t(y) * stride);
    for (std::size_t i = 3; i < image.size(); i += 4)
        image[i] = 255; // the window is opaque, whatever its visual keeps of alpha
    if (Status written = writeImage(path, uint32_t(width), uint32_t(height), image); !written)
        return written;
    summary_.screenshots.push_back(path);
    return Status::ok();
}

Result<ViewerSummary> Viewer::run() {
    const Clock::time_point start = Clock::now();
    // With a frame count (tests, screenshots) each frame is rendered and shown before the next
    // is asked for, and the script's events fall between them: the run is deterministic.
    // Without, frames are asked for whenever the worker is free, and input keeps flowing.
    const bool lockstep = settings_.frames > 0;
    while (!quit_ && !glfwWindowShouldClose(window_)) {
        if (lockstep) {
            applyScript(summary_.frames);
            if (!pending_error_.empty() || quit_)
                break;
            worker_->submit(request());
            show(worker_->wait());
            glfwPollEvents();
        } else {
            glfwWaitEventsTimeout(shown_ && !dirty_ && !(playing_ && animated_) ? 0.05 : 0.005);
            applyScript(summary_.frames);
            if (std::optional<RenderedFrame> frame = worker_->take())
                show(std::move(*frame));
            if (!worker_->busy() && (dirty_ || (playing_ && animated_))) {
                dirty_ = false;
                worker_->submit(request());
            }
        }
        if (!pending_error_.empty())
            break;
        drawWindow();
        // Screenshots read the drawn back buffer, before it is shown.
        if (screenshot_asked_) {
            screenshot_asked_ = false;
            // The first free name: a screenshot never replaces a file (an earlier run's, an input).
            std::string path;
            std::error_code ignored;
            do
                path = "vissort-view-" + std::to_string(++screenshot_count_) + ".png";
            while (std::filesystem::exists(path, ignored));
            if (Status saved = saveScreenshot(path); !saved)
                pending_error_ = saved.error;
        }
        if (lockstep && summary_.frames >= settings_.frames) {
            if (!settings_.screenshot.empty())
                if (Status saved = saveScreenshot(settings_.screenshot); !saved)
                    pending_error_ = saved.error;
            break;
        }
        glfwSwapBuffers(window_);
    }
    if (!pending_error_.empty())
        return {std::nullopt, pending_error_};
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    summary_.fps = seconds > 0 ? summary_.frames / seconds : 0;
    if (!all_ms_.empty()) {
        std::vector<double> sorted = all_ms_;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        summary_.median_ms = sorted[sorted.size() / 2];
    }
    if (summary_.frames == 0)
        summary_.camera = currentCamera();
    return {summary_, ""};
}

} // namespace

Status checkDisplay() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((x11 == nullptr || *x11 == '\0') && (wayland == nullptr || *wayland == '\0'))
        return Status::failure("view needs a display (X11 or Wayland; DISPLAY and WAYLAND_DISPLAY "
                               "are unset): run it under xvfb-run, or write images with "
                               "vissort render");
    return Status::ok();
}

Result<ViewerSummary> runViewer(const Scene& scene, const ViewerSettings& settings) {
    Viewer viewer(scene, nullptr, settings);
    if (Status opened = viewer.open(); !opened)
        return {std::nullopt, opened.error};
    return viewer.run();
}

Result<ViewerSummary> runVolumeViewer(const TetGrid& grid, const Scene& boundary,
                                      const ViewerSettings& settings) {
    if (!settings.volume)
        return {std::nullopt, "a grid's viewer needs its volume settings"};
    Viewer viewer(boundary, &grid, settings);
    if (Status opened = viewer.open(); !opened)
        return {std::nullopt, opened.error};
    return viewer.run();
}

} // namespace vissort::viewer
