#include "report/report_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace fxport::report {

std::vector<std::size_t> paretoFront(const std::vector<Measurement>& rows) {
    std::vector<std::size_t> front;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!rows[i].sameScene) continue;
        bool dominated = false;
        for (std::size_t j = 0; j < rows.size() && !dominated; ++j)
            dominated = j != i && rows[j].sameScene && rows[j].frameMs <= rows[i].frameMs && rows[j].error.rms <= rows[i].error.rms &&
                        (rows[j].frameMs < rows[i].frameMs || rows[j].error.rms < rows[i].error.rms);
        if (!dominated) front.push_back(i);
    }
    std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) { return rows[a].frameMs < rows[b].frameMs; });
    return front;
}

namespace {

struct Canvas {
    int w, h;
    std::vector<Color> px;
    Canvas(int w_, int h_) : w(w_), h(h_), px(std::size_t(w_) * std::size_t(h_), Color::White) {}
    void dot(int x, int y, Color c) {
        if (x >= 0 && y >= 0 && x < w && y < h) px[std::size_t(y) * std::size_t(w) + std::size_t(x)] = c;
    }
    void disc(double cx, double cy, double r, Color c, bool ring = false) {
        for (int y = int(cy - r - 1); y <= int(cy + r + 1); ++y)
            for (int x = int(cx - r - 1); x <= int(cx + r + 1); ++x) {
                const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
                if (ring ? std::fabs(d - r) < 1.0 : d <= r) dot(x, y, c);
            }
    }
    // A line `thick` pixels wide; dashed when dash > 0 (on/off lengths in pixels).
    void line(double x0, double y0, double x1, double y1, Color c, double thick = 2, double dash = 0) {
        const double len = std::hypot(x1 - x0, y1 - y0);
        const int steps = std::max(1, int(len * 2));
        for (int i = 0; i <= steps; ++i) {
            const double t = double(i) / steps;
            if (dash > 0 && std::fmod(t * len, 2 * dash) > dash) continue;
            const double x = x0 + (x1 - x0) * t, y = y0 + (y1 - y0) * t;
            for (int dy = 0; dy < int(thick); ++dy)
                for (int dx = 0; dx < int(thick); ++dx) dot(int(x - thick / 2 + dx + 0.5), int(y - thick / 2 + dy + 0.5), c);
        }
    }
    void rect(int x0, int y0, int x1, int y1, Color c) {
        line(x0, y0, x1, y0, c, 1), line(x1, y0, x1, y1, c, 1), line(x1, y1, x0, y1, c, 1), line(x0, y1, x0, y0, c, 1);
    }
};

struct Text {
    std::string s;
    Vector2 at;
    Color color;
    bool vertical = false;
    float scale = 1;
};

const Color kPalette[] = {Color(31, 119, 180), Color(214, 39, 40), Color(44, 160, 44), Color(148, 103, 189),
                          Color(255, 127, 14), Color(23, 190, 207), Color(140, 86, 75)};

std::string number(double v) {
    char buf[32];
    if (v >= 1000 || v < 0.001) std::snprintf(buf, sizeof buf, "%.0e", v);
    else std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

void panel(Canvas& canvas, std::vector<Text>& texts, const std::vector<Measurement>& rows, const std::string& name,
           int px, int py, int pw, int ph) {
    const int left = px + 80, right = px + pw - 20, top = py + 40, bottom = py + ph - 150;
    texts.push_back({name, Vector2(float(px + pw / 2 - int(name.size()) * 8), float(py + 12)), Color::Black, false, 2});
    canvas.rect(left, top, right, bottom, Color(80, 80, 80));
    // The y axis is the RMS error; rows with RMS 0 (exact) would be at -infinity: drawn at the floor.
    double t0 = 1e300, t1 = 0, e0 = 1e300, e1 = 0;
    for (const Measurement& m : rows) {
        t0 = std::min(t0, m.frameMs), t1 = std::max(t1, m.frameMs);
        if (m.error.rms > 0) e0 = std::min(e0, m.error.rms), e1 = std::max(e1, m.error.rms);
    }
    if (rows.empty() || t1 <= 0) return;
    t0 = std::max(t0, 1e-4);
    if (e1 <= 0) e0 = 1e-4, e1 = 1e-3;
    // Whole decades, at least one.
    const double lt0 = std::floor(std::log10(t0)), lt1 = std::max(lt0 + 1, std::ceil(std::log10(t1)));
    const double le0 = std::floor(std::log10(e0)), le1 = std::max(le0 + 1, std::ceil(std::log10(e1)));
    auto X = [&](double t) { return left + (std::log10(std::max(t, 1e-12)) - lt0) / (lt1 - lt0) * (right - left); };
    auto Y = [&](double e) {
        return bottom - (std::log10(std::max(e, std::pow(10.0, le0))) - le0) / (le1 - le0) * (bottom - top);
    };
    for (double d = lt0; d <= lt1 + 1e-9; ++d) {
        for (int k = 2; k <= 9 && d < lt1; ++k) canvas.line(X(k * std::pow(10, d)), top, X(k * std::pow(10, d)), bottom, Color(235, 235, 235), 1);
        canvas.line(X(std::pow(10, d)), top, X(std::pow(10, d)), bottom, Color(200, 200, 200), 1);
        const std::string label = number(std::pow(10, d));
        texts.push_back({label, Vector2(float(X(std::pow(10, d)) - 4 * label.size()), float(bottom + 6)), Color::Black});
    }
    for (double d = le0; d <= le1 + 1e-9; ++d) {
        for (int k = 2; k <= 9 && d < le1; ++k) canvas.line(left, Y(k * std::pow(10, d)), right, Y(k * std::pow(10, d)), Color(235, 235, 235), 1);
        canvas.line(left, Y(std::pow(10, d)), right, Y(std::pow(10, d)), Color(200, 200, 200), 1);
        const std::string label = number(std::pow(10, d));
        texts.push_back({label, Vector2(float(left - 8 - 8 * int(label.size())), float(Y(std::pow(10, d)) - 4)), Color::Black});
    }
    texts.push_back({"median GPU frame time (ms, log)", Vector2(float((left + right) / 2 - 124), float(bottom + 22)), Color::Black});
    texts.push_back({"RMS error (log)", Vector2(float(px + 14), float((top + bottom) / 2 + 60)), Color::Black, true});

    // One curve per knob, in sweep order.
    std::map<std::string, std::vector<std::size_t>> byKnob;
    std::vector<std::string> knobOrder;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!byKnob.count(rows[i].knob)) knobOrder.push_back(rows[i].knob);
        byKnob[rows[i].knob].push_back(i);
    }
    const std::vector<std::size_t> front = paretoFront(rows);
    for (std::size_t i = 1; i < front.size(); ++i) {  // the front as a dashed staircase
        const Measurement &a = rows[front[i - 1]], &b = rows[front[i]];
        canvas.line(X(a.frameMs), Y(a.error.rms), X(b.frameMs), Y(a.error.rms), Color(60, 60, 60), 2, 6);
        canvas.line(X(b.frameMs), Y(a.error.rms), X(b.frameMs), Y(b.error.rms), Color(60, 60, 60), 2, 6);
    }
    for (std::size_t k = 0; k < knobOrder.size(); ++k) {
        const Color c = kPalette[k % (sizeof kPalette / sizeof kPalette[0])];
        const std::vector<std::size_t>& idx = byKnob[knobOrder[k]];
        for (std::size_t i = 1; i < idx.size(); ++i)
            canvas.line(X(rows[idx[i - 1]].frameMs), Y(rows[idx[i - 1]].error.rms), X(rows[idx[i]].frameMs),
                        Y(rows[idx[i]].error.rms), c, 2);
        for (std::size_t i : idx) {
            canvas.disc(X(rows[i].frameMs), Y(rows[i].error.rms), rows[i].seedDefault ? 6 : 4, c);
            if (rows[i].seedDefault) canvas.disc(X(rows[i].frameMs), Y(rows[i].error.rms), 3, Color::White);
        }
        // Label each curve's first and last setting.
        // (Not the seed's setting: every curve passes through it.)
        for (std::size_t i : {idx.front(), idx.back()}) {
            if (rows[i].seedDefault) continue;
            std::string s = rows[i].setting.substr(0, 22);
            texts.push_back({s, Vector2(float(X(rows[i].frameMs) + 8), float(Y(rows[i].error.rms) - 12)), c});
            if (idx.size() == 1) break;
        }
        // Legend below the axes.
        const int ly = bottom + 44 + int(k) * 14;
        canvas.line(left, ly + 4, left + 24, ly + 4, c, 3);
        texts.push_back({knobOrder[k] + (rows[idx.back()].sameScene ? "" : " (changes the scene: not in the Pareto front)"),
                         Vector2(float(left + 32), float(ly)), Color::Black});
    }
    for (std::size_t i : front) canvas.disc(X(rows[i].frameMs), Y(rows[i].error.rms), 9, Color::Black, true);
    const int ly = bottom + 44 + int(knobOrder.size()) * 14;
    canvas.disc(left + 12, ly + 4, 6, Color::Black, true);
    canvas.line(left + 22, ly + 4, left + 46, ly + 4, Color(60, 60, 60), 2, 6);
    texts.push_back({"Pareto front (nothing both faster and more exact)", Vector2(float(left + 52), float(ly)), Color::Black});
    canvas.disc(left + 12, ly + 18, 6, Color(120, 120, 120));
    canvas.disc(left + 12, ly + 18, 3, Color::White);
    texts.push_back({"the seed's setting", Vector2(float(left + 32), float(ly + 14)), Color::Black});
}

}  // namespace

void writePlot(GraphicsDevice& device, const std::vector<Measurement>& measured, const std::string& title, const std::string& path) {
    // A second error (the deferred light map against its exact reference) gets a panel of its own.
    std::vector<Measurement> rows = measured;
    for (const Measurement& m : measured)
        if (m.hasLightMapError) {
            Measurement lm = m;
            lm.demo = m.demo + ": light map vs exact";
            lm.error = m.lightMapError;
            rows.push_back(lm);
        }
    std::vector<std::string> demos;
    for (const Measurement& m : rows)
        if (std::find(demos.begin(), demos.end(), m.demo) == demos.end()) demos.push_back(m.demo);
    const int pw = 800, ph = 620, cols = 2, rowsN = std::max(1, int(demos.size() + 1) / 2);
    Canvas canvas(pw * cols, 40 + ph * rowsN);
    std::vector<Text> texts;
    texts.push_back({title, Vector2(10, 10), Color::Black, false, 2});
    for (std::size_t d = 0; d < demos.size(); ++d) {
        std::vector<Measurement> mine;
        for (const Measurement& m : rows)
            if (m.demo == demos[d]) mine.push_back(m);
        panel(canvas, texts, mine, demos[d], int(d % 2) * pw, 40 + int(d / 2) * ph, pw, ph);
    }
    Texture2D image(device, canvas.w, canvas.h);
    image.SetData(canvas.px);
    RenderTarget2D target(device, canvas.w, canvas.h);
    auto font = SpriteFont::createDebugFont(device);
    SpriteBatch batch(device);
    device.SetRenderTarget(&target);
    device.Clear(Color::White);
    batch.Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
    batch.Draw(image, Vector2(0, 0), Color::White);
    batch.End();
    batch.Begin(SpriteSortMode::Deferred, BlendState::AlphaBlend, SamplerState::PointClamp, nullptr, nullptr);
    for (const Text& t : texts)
        batch.DrawString(*font, t.s, t.at, t.color, t.vertical ? -MathHelper::PiOver2 : 0.f, Vector2(0, 0), t.scale,
                         SpriteEffects::None, 0);
    batch.End();
    device.SetRenderTarget(nullptr);
    target.SaveAsPng(path);
}

}  // namespace fxport::report
