#include "perception/vision/object_drawings.h"

#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace alplan::perception {
namespace {

// Draws on the canvas and marks the mask, in unit coordinates: (0, 0) is
// the centre, (+-1, +-1) the corners of a square `size` pixels wide.
class Pen {
 public:
  Pen(cv::Mat& canvas, cv::Mat& mask, cv::Point2f centre, float size) : canvas_(canvas), mask_(mask), c_(centre), s_(size / 2) {}

  cv::Point at(float x, float y) const { return {cvRound(c_.x + x * s_), cvRound(c_.y + y * s_)}; }
  int length(float u) const { return std::max(1, cvRound(u * s_)); }

  void rect(float x0, float y0, float x1, float y1, const cv::Scalar& colour) { poly({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, colour); }
  void poly(const std::vector<cv::Point2f>& unit, const cv::Scalar& colour) {
    std::vector<cv::Point> points;
    for (const cv::Point2f& p : unit) points.push_back(at(p.x, p.y));
    cv::fillPoly(canvas_, std::vector<std::vector<cv::Point>>{points}, colour, cv::LINE_AA);
    cv::fillPoly(mask_, std::vector<std::vector<cv::Point>>{points}, 255);
  }
  void ellipse(float x, float y, float rx, float ry, const cv::Scalar& colour, int thickness = cv::FILLED,
               float angle = 0, float from = 0, float to = 360) {
    cv::ellipse(canvas_, at(x, y), {length(rx), length(ry)}, angle, from, to, colour, thickness, cv::LINE_AA);
    cv::ellipse(mask_, at(x, y), {length(rx), length(ry)}, angle, from, to, 255, thickness, cv::LINE_AA);
  }
  void line(float x0, float y0, float x1, float y1, const cv::Scalar& colour, float width) {
    cv::line(canvas_, at(x0, y0), at(x1, y1), colour, length(width), cv::LINE_AA);
    cv::line(mask_, at(x0, y0), at(x1, y1), 255, length(width), cv::LINE_AA);
  }
  // Marks on the object (text, lines) that do not change its outline.
  void mark(float x0, float y0, float x1, float y1, const cv::Scalar& colour, int thickness = 1) {
    cv::line(canvas_, at(x0, y0), at(x1, y1), colour, thickness, cv::LINE_AA);
  }
  void text(const std::string& t, float x, float y, float scale, const cv::Scalar& colour) {
    cv::putText(canvas_, t, at(x, y), cv::FONT_HERSHEY_SIMPLEX, scale * s_ / 40.0, colour, 1, cv::LINE_AA);
  }

 private:
  cv::Mat& canvas_;
  cv::Mat& mask_;
  cv::Point2f c_;
  float s_;
};

float uniform(std::mt19937& rng, float low, float high) { return std::uniform_real_distribution<float>(low, high)(rng); }

cv::Scalar random_colour(std::mt19937& rng, int low = 30, int high = 230) {
  std::uniform_int_distribution<int> d(low, high);
  return cv::Scalar(d(rng), d(rng), d(rng));
}

cv::Scalar shade(const cv::Scalar& c, double f) { return cv::Scalar(c[0] * f, c[1] * f, c[2] * f); }

void text_lines(Pen& pen, float x0, float x1, float y0, float y1, int lines, const cv::Scalar& ink, std::mt19937& rng) {
  for (int i = 0; i < lines; ++i) {
    const float y = y0 + (y1 - y0) * (static_cast<float>(i) + 0.5f) / static_cast<float>(lines);
    pen.mark(x0, y, x0 + (x1 - x0) * uniform(rng, 0.6f, 1.0f), y, ink);
  }
}

void draw_book(Pen& p, std::mt19937& rng) {
  const cv::Scalar cover = random_colour(rng, 20, 200);
  const float w = uniform(rng, 0.55f, 0.7f);
  p.rect(-w, -0.95f, w, 0.95f, cover);
  p.rect(w - 0.08f, -0.9f, w + 0.06f, 0.9f, {235, 240, 245});  // page edges
  for (int i = 0; i < 5; ++i) p.mark(w - 0.06f + 0.025f * static_cast<float>(i), -0.88f, w - 0.06f + 0.025f * static_cast<float>(i), 0.88f, {180, 185, 190});
  p.rect(-w, -0.95f, -w + 0.15f, 0.95f, shade(cover, 0.6));  // spine
  p.rect(-w + 0.3f, -0.55f, w - 0.2f, -0.3f, shade(cover, 1.5));  // title plate
}

void draw_magazine(Pen& p, std::mt19937& rng) {
  const float w = uniform(rng, 0.6f, 0.72f);
  p.rect(-w, -0.95f, w, 0.95f, random_colour(rng, 120, 255));
  p.rect(-w, -0.95f, w, -0.62f, random_colour(rng, 0, 120));  // masthead band
  p.text("MAG", -w + 0.05f, -0.68f, 0.9f, {255, 255, 255});
  p.ellipse(uniform(rng, -0.2f, 0.2f), 0.25f, 0.38f, 0.45f, random_colour(rng));  // cover photo
  p.rect(-w + 0.08f, 0.72f, w - 0.08f, 0.82f, random_colour(rng, 0, 255));
}

void draw_journal(Pen& p, std::mt19937& rng) {
  const cv::Scalar leather = random_colour(rng, 10, 110);
  const float w = uniform(rng, 0.5f, 0.62f);
  p.rect(-w, -0.85f, w, 0.85f, leather);
  p.ellipse(-w, -0.85f, 0.08f, 0.08f, leather);
  p.ellipse(w, 0.85f, 0.08f, 0.08f, leather);
  p.line(w - 0.18f, -0.9f, w - 0.18f, 0.9f, {20, 20, 20}, 0.06f);  // elastic strap
  p.line(-w + 0.25f, 0.88f, -w + 0.25f, 1.0f, {40, 40, 200}, 0.05f);  // ribbon
}

void draw_newspaper(Pen& p, std::mt19937& rng) {
  const float h = uniform(rng, 0.6f, 0.75f);
  p.rect(-0.95f, -h, 0.95f, h, {215, 220, 222});
  p.rect(-0.9f, -h + 0.05f, 0.9f, -h + 0.25f, {40, 40, 40});  // headline
  const int columns = 3 + static_cast<int>(rng() % 2);
  for (int c = 0; c < columns; ++c) {
    const float x0 = -0.9f + 1.8f * static_cast<float>(c) / static_cast<float>(columns);
    text_lines(p, x0 + 0.02f, x0 + 1.8f / static_cast<float>(columns) - 0.06f, -h + 0.32f, h - 0.05f, 9, {70, 70, 70}, rng);
  }
  p.rect(-0.85f, -h + 0.35f, -0.35f, -0.05f, {120, 120, 120});  // photo
}

void draw_story(Pen& p, std::mt19937& rng) {
  const cv::Scalar cover = random_colour(rng, 20, 160);
  p.poly({{-1.0f, -0.6f}, {0.0f, -0.5f}, {1.0f, -0.6f}, {1.0f, 0.7f}, {0.0f, 0.8f}, {-1.0f, 0.7f}}, cover);
  p.poly({{-0.95f, -0.65f}, {-0.02f, -0.52f}, {-0.02f, 0.7f}, {-0.95f, 0.6f}}, {245, 245, 240});
  p.poly({{0.02f, -0.52f}, {0.95f, -0.65f}, {0.95f, 0.6f}, {0.02f, 0.7f}}, {245, 245, 240});
  text_lines(p, -0.85f, -0.1f, -0.45f, 0.55f, 8, {60, 60, 60}, rng);
  text_lines(p, 0.1f, 0.85f, -0.45f, 0.55f, 8, {60, 60, 60}, rng);
  p.mark(0.0f, -0.52f, 0.0f, 0.72f, {90, 90, 90}, 2);
}

void draw_sudoku(Pen& p, std::mt19937& rng) {
  p.rect(-0.85f, -0.85f, 0.85f, 0.85f, {250, 250, 250});
  for (int i = 0; i <= 9; ++i) {
    const float u = -0.85f + 1.7f * static_cast<float>(i) / 9.0f;
    const int t = i % 3 == 0 ? 2 : 1;
    p.mark(u, -0.85f, u, 0.85f, {0, 0, 0}, t);
    p.mark(-0.85f, u, 0.85f, u, {0, 0, 0}, t);
  }
  for (int k = 0; k < 14; ++k) {
    const int r = static_cast<int>(rng() % 9), c = static_cast<int>(rng() % 9);
    p.text(std::to_string(1 + rng() % 9), -0.82f + 1.7f * static_cast<float>(c) / 9.0f, -0.68f + 1.7f * static_cast<float>(r) / 9.0f, 0.35f, {30, 30, 30});
  }
}

void draw_puzzle(Pen& p, std::mt19937& rng) {
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 2; ++c) {
      const cv::Scalar colour = random_colour(rng);
      const float x = -0.45f + 0.9f * static_cast<float>(c), y = -0.45f + 0.9f * static_cast<float>(r);
      p.rect(x - 0.36f, y - 0.36f, x + 0.36f, y + 0.36f, colour);
      p.ellipse(x + 0.42f, y, 0.13f, 0.13f, colour);  // knobs
      p.ellipse(x, y + 0.42f, 0.13f, 0.13f, colour);
      p.ellipse(x - 0.36f, y, 0.1f, 0.1f, {0, 0, 0}, 1);  // sockets
    }
  }
}

void draw_magic_cube(Pen& p, std::mt19937& rng) {
  static const std::array<cv::Scalar, 6> kStickers = {cv::Scalar(0, 0, 220),   cv::Scalar(0, 170, 0),   cv::Scalar(200, 60, 0),
                                                     cv::Scalar(0, 220, 230), cv::Scalar(245, 245, 245), cv::Scalar(0, 120, 255)};
  const cv::Point2f top(0, -0.9f), left(-0.8f, -0.45f), right(0.8f, -0.45f), middle(0, 0), bottom(0, 0.9f),
      low_left(-0.8f, 0.45f), low_right(0.8f, 0.45f);
  p.poly({top, right, low_right, bottom, low_left, left}, {20, 20, 20});
  const auto face = [&](cv::Point2f o, cv::Point2f u, cv::Point2f v) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const auto pt = [&](float a, float b) { return o + u * (a / 3.0f) + v * (b / 3.0f); };
        const float fi = static_cast<float>(i), fj = static_cast<float>(j);
        p.poly({pt(fi + 0.1f, fj + 0.1f), pt(fi + 0.9f, fj + 0.1f), pt(fi + 0.9f, fj + 0.9f), pt(fi + 0.1f, fj + 0.9f)},
               kStickers[rng() % kStickers.size()]);
      }
    }
  };
  face(left, top - left, middle - left);
  face(left, middle - left, low_left - left);
  face(middle, right - middle, bottom - middle);
}

void draw_yoyo(Pen& p, std::mt19937& rng) {
  const cv::Scalar colour = random_colour(rng);
  p.line(0, -0.95f, 0, 0.0f, {230, 230, 230}, 0.03f);  // string
  p.ellipse(0, 0.3f, 0.62f, 0.62f, colour);
  p.ellipse(0, 0.3f, 0.5f, 0.5f, shade(colour, 0.7), 2);
  p.ellipse(0, 0.3f, 0.14f, 0.14f, {200, 200, 200});
}

void draw_cup(Pen& p, std::mt19937& rng) {
  const cv::Scalar colour = random_colour(rng, 120, 255);
  p.ellipse(0, 0.72f, 0.95f, 0.2f, shade(colour, 0.85));  // saucer
  p.ellipse(0.6f, 0.05f, 0.22f, 0.2f, colour, std::max(2, p.length(0.08f)));  // small handle
  p.poly({{-0.62f, -0.45f}, {0.62f, -0.45f}, {0.4f, 0.62f}, {-0.4f, 0.62f}}, colour);
  p.ellipse(0, -0.45f, 0.62f, 0.12f, shade(colour, 0.6));  // rim
}

void draw_mug(Pen& p, std::mt19937& rng) {
  const cv::Scalar colour = random_colour(rng);
  p.ellipse(0.5f, 0.05f, 0.38f, 0.42f, colour, std::max(3, p.length(0.16f)));  // big handle
  p.rect(-0.55f, -0.7f, 0.5f, 0.8f, colour);
  p.ellipse(-0.025f, -0.7f, 0.525f, 0.12f, shade(colour, 0.55));
  p.ellipse(-0.025f, 0.8f, 0.525f, 0.1f, colour);
}

void draw_jar(Pen& p, std::mt19937& rng) {
  const cv::Scalar glass = random_colour(rng, 150, 240);
  p.rect(-0.6f, -0.45f, 0.6f, 0.75f, glass);
  p.ellipse(0, 0.75f, 0.6f, 0.14f, glass);
  p.ellipse(-0.6f, -0.4f, 0.1f, 0.1f, glass);
  p.ellipse(0.6f, -0.4f, 0.1f, 0.1f, glass);
  p.rect(-0.5f, -0.75f, 0.5f, -0.45f, random_colour(rng, 20, 120));  // lid
  p.rect(-0.55f, 0.05f, 0.55f, 0.75f, shade(random_colour(rng), 0.8));  // contents
}

void draw_drinking_glass(Pen& p, std::mt19937& rng) {
  const cv::Scalar tint(230, 225, 215);
  p.poly({{-0.5f, -0.9f}, {0.5f, -0.9f}, {0.36f, 0.9f}, {-0.36f, 0.9f}}, tint);
  p.poly({{-0.44f, -0.1f + uniform(rng, -0.3f, 0.3f)}, {0.44f, -0.1f}, {0.36f, 0.88f}, {-0.36f, 0.88f}},
         random_colour(rng, 60, 220));  // drink
  p.mark(-0.5f, -0.9f, -0.36f, 0.9f, {160, 160, 160}, 2);
  p.mark(0.5f, -0.9f, 0.36f, 0.9f, {160, 160, 160}, 2);
  p.ellipse(0, -0.9f, 0.5f, 0.08f, {160, 160, 160}, 1);
}

void draw_glass_bottle(Pen& p, std::mt19937& rng) {
  const cv::Scalar glass = std::array<cv::Scalar, 3>{cv::Scalar(40, 120, 40), cv::Scalar(30, 70, 120), cv::Scalar(200, 200, 190)}[rng() % 3];
  p.rect(-0.35f, -0.2f, 0.35f, 0.95f, glass);
  p.poly({{-0.35f, -0.2f}, {0.35f, -0.2f}, {0.12f, -0.55f}, {-0.12f, -0.55f}}, glass);
  p.rect(-0.12f, -0.88f, 0.12f, -0.55f, glass);
  p.rect(-0.14f, -0.98f, 0.14f, -0.85f, random_colour(rng));  // cap
  p.rect(-0.35f, 0.15f, 0.35f, 0.55f, random_colour(rng, 150, 255));  // label
}

void draw_drum(Pen& p, std::mt19937& rng) {
  const cv::Scalar shell = random_colour(rng);
  p.rect(-0.75f, -0.3f, 0.75f, 0.55f, shell);
  p.ellipse(0, 0.55f, 0.75f, 0.2f, shell);
  p.ellipse(0, -0.3f, 0.75f, 0.2f, {235, 235, 235});  // drum head
  for (int i = 0; i < 6; ++i) {
    const float x = -0.65f + 0.26f * static_cast<float>(i);
    p.mark(x, -0.25f, x + 0.13f, 0.6f, {210, 210, 210}, 2);  // tension rods
  }
  p.line(-0.7f, -0.95f, 0.15f, -0.35f, {60, 110, 170}, 0.05f);  // sticks
  p.line(0.7f, -0.95f, -0.15f, -0.35f, {60, 110, 170}, 0.05f);
}

void draw_clarinet(Pen& p, std::mt19937& rng) {
  const float lean = uniform(rng, -0.25f, 0.25f);
  p.line(-lean, -0.95f, lean, 0.7f, {25, 25, 25}, 0.14f);
  p.poly({{lean - 0.09f, 0.6f}, {lean + 0.09f, 0.6f}, {lean + 0.22f, 0.97f}, {lean - 0.22f, 0.97f}}, {25, 25, 25});  // bell
  for (int i = 0; i < 7; ++i) {
    const float t = 0.15f + 0.1f * static_cast<float>(i);
    const float x = -lean + 2 * lean * t, y = -0.95f + 1.65f * t;
    p.ellipse(x, y, 0.035f, 0.035f, {200, 200, 200});  // keys
  }
}

void draw_body(Pen& p, float upper, float lower, float waist, float length, const cv::Scalar& colour) {
  p.ellipse(0, 0.45f * length, lower, lower * 0.95f, colour);
  p.ellipse(0, -0.05f * length, upper, upper * 0.95f, colour);
  p.rect(-waist, -0.05f * length, waist, 0.45f * length, colour);
}

void draw_guitar(Pen& p, std::mt19937& rng) {
  const cv::Scalar wood = std::array<cv::Scalar, 3>{cv::Scalar(40, 110, 190), cv::Scalar(30, 60, 110), cv::Scalar(20, 20, 20)}[rng() % 3];
  draw_body(p, 0.32f, 0.42f, 0.28f, 1.0f, wood);
  p.ellipse(0, 0.12f, 0.11f, 0.11f, {15, 15, 15});  // sound hole
  p.rect(-0.06f, -0.95f, 0.06f, 0.0f, {30, 50, 80});  // neck
  p.rect(-0.09f, -1.0f, 0.09f, -0.82f, {30, 40, 60});  // head
  for (int s = 0; s < 3; ++s) p.mark(-0.04f + 0.04f * static_cast<float>(s), -0.95f, -0.04f + 0.04f * static_cast<float>(s), 0.6f, {220, 220, 220});
}

void draw_violin(Pen& p, std::mt19937& rng) {
  const cv::Scalar varnish(20, 70 + static_cast<int>(rng() % 40), 150 + static_cast<int>(rng() % 60));
  draw_body(p, 0.26f, 0.32f, 0.16f, 1.0f, varnish);
  p.mark(-0.12f, 0.05f, -0.1f, 0.35f, {10, 10, 10}, 2);  // f-holes
  p.mark(0.12f, 0.05f, 0.1f, 0.35f, {10, 10, 10}, 2);
  p.rect(-0.04f, -0.9f, 0.04f, -0.2f, {10, 10, 10});  // fingerboard
  p.ellipse(0, -0.93f, 0.07f, 0.07f, shade(varnish, 0.8));  // scroll
  p.line(-0.85f, 0.7f, 0.8f, -0.5f, {60, 100, 140}, 0.03f);  // bow
}

}  // namespace

const std::vector<ObjectClassDrawing>& object_class_drawings() {
  static const std::vector<ObjectClassDrawing> kDrawings = [] {
    const auto wrap = [](void (*draw)(Pen&, std::mt19937&)) {
      return [draw](cv::Mat& canvas, cv::Mat& mask, cv::Point2f centre, float size, std::mt19937& rng) {
        Pen pen(canvas, mask, centre, size);
        draw(pen, rng);
      };
    };
    return std::vector<ObjectClassDrawing>{
        {"book", wrap(draw_book)},           {"clarinet", wrap(draw_clarinet)},
        {"cup", wrap(draw_cup)},             {"drinking_glass", wrap(draw_drinking_glass)},
        {"drum", wrap(draw_drum)},           {"glass_bottle", wrap(draw_glass_bottle)},
        {"guitar", wrap(draw_guitar)},       {"jar", wrap(draw_jar)},
        {"journal", wrap(draw_journal)},     {"magazine", wrap(draw_magazine)},
        {"magic_cube", wrap(draw_magic_cube)}, {"mug", wrap(draw_mug)},
        {"newspaper", wrap(draw_newspaper)}, {"puzzle", wrap(draw_puzzle)},
        {"story", wrap(draw_story)},         {"sudoku", wrap(draw_sudoku)},
        {"violin", wrap(draw_violin)},       {"yoyo", wrap(draw_yoyo)}};
  }();
  return kDrawings;
}

}  // namespace alplan::perception
