#include "modeling/synthesis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "engine/scene/texture_detail.h"

namespace pw::modeling {
namespace {

constexpr int kCell = 16;               // the footprint is evaluated once per cell
// A photo pixel's spread in texels, relative to the least anywhere on the surface: at
// most this for the exemplar; beyond the other, detail is added.
constexpr double kSharpSpread = 2.5;
constexpr double kCoarseSpread = 1.4;  // times the exemplar's own
constexpr double kBlurPerSpread = 0.45;  // Gaussian sigma of a photo pixel's blur, per texel of its spread
// How much of the exemplar's detail a tile gets: a lattice continued from the exemplar
// puts it in phase to a fraction of a texel, yet the photo's own coarse view of the tile
// keeps some of it (0.85 brings the high-frequency energy at mid-corridor to POV-Ray's
// 0.73; 1.0 costs 0.4 dB, 0.7 falls short at 0.58: novel_view_bench); surfaces that do
// not repeat, whose detail can only be plausible, get less.
constexpr double kDetailGain = 0.85;
constexpr double kRandomDetailGain = 0.7;
constexpr int kTile = 48;
constexpr int kStride = 36;

// A photo pixel's footprint on the texture at one cell.
struct Cell {
  bool covered = false;
  double spreadX = 0, spreadY = 0;  // texels one photo pixel spans along x and y
};

struct Grid {
  int cols = 0, rows = 0;
  std::vector<Cell> cells;
  const Cell& at(int cx, int cy) const { return cells[static_cast<size_t>(cy) * cols + cx]; }
};

bool insidePhoto(const glm::dvec2& p, cv::Size size, double marginPx = 0) {
  return p.x >= marginPx - 0.5 && p.y >= marginPx - 0.5 && p.x <= size.width - 0.5 - marginPx &&
         p.y <= size.height - 0.5 - marginPx;
}

// The photo's outermost pixels reach the texture through a bicubic filter that sees
// beyond the photo: texels within this of its border count as not shown.
constexpr double kBorderPx = 2.0;

Grid footprints(cv::Size textureSize, const PhotoOfTexel& photoOf, cv::Size photoSize) {
  Grid g;
  g.cols = (textureSize.width + kCell - 1) / kCell;
  g.rows = (textureSize.height + kCell - 1) / kCell;
  g.cells.resize(static_cast<size_t>(g.cols) * g.rows);
  for (int cy = 0; cy < g.rows; ++cy) {
    for (int cx = 0; cx < g.cols; ++cx) {
      const double x = std::min(cx * kCell + 0.5 * kCell, textureSize.width - 1.0);
      const double y = std::min(cy * kCell + 0.5 * kCell, textureSize.height - 1.0);
      const auto p = photoOf(x, y), px = photoOf(x + 1, y), py = photoOf(x, y + 1);
      Cell& c = g.cells[static_cast<size_t>(cy) * g.cols + cx];
      if (!p || !px || !py || !insidePhoto(*p, photoSize)) continue;
      const glm::dvec2 jx = *px - *p, jy = *py - *p;  // photo pixels per texel along x, y
      const double det = jx.x * jy.y - jy.x * jx.y;
      if (!(std::abs(det) > 1e-12)) continue;
      // Texel offsets of a photo pixel's offsets: the inverse; a pixel's extent along x
      // and y is the sum of the absolute entries of each row.
      c.covered = true;
      c.spreadX = (std::abs(jy.y) + std::abs(jy.x)) / std::abs(det);
      c.spreadY = (std::abs(jx.y) + std::abs(jx.x)) / std::abs(det);
    }
  }
  return g;
}

// Texel coverage: a cell whose four corners the photo shows is shown whole (the photo's
// frame maps to a convex region of the plane); the others are evaluated per texel.
// `marginPx`: texels within this of the photo's border count as not shown.
cv::Mat1b coverage(cv::Size size, const PhotoOfTexel& photoOf, cv::Size photoSize, double marginPx = kBorderPx) {
  cv::Mat1b mask(size, uint8_t(0));
  const auto shows = [&](double x, double y) {
    const auto p = photoOf(x, y);
    return p && insidePhoto(*p, photoSize, marginPx);
  };
  for (int y0 = 0; y0 < size.height; y0 += kCell) {
    for (int x0 = 0; x0 < size.width; x0 += kCell) {
      const int x1 = std::min(size.width, x0 + kCell) - 1, y1 = std::min(size.height, y0 + kCell) - 1;
      const int corners = shows(x0, y0) + shows(x1, y0) + shows(x0, y1) + shows(x1, y1);
      if (corners == 4) {
        mask(cv::Rect(x0, y0, x1 - x0 + 1, y1 - y0 + 1)).setTo(255);
      } else {
        for (int y = y0; y <= y1; ++y) {
          for (int x = x0; x <= x1; ++x) mask(y, x) = shows(x, y) ? 255 : 0;
        }
      }
    }
  }
  return mask;
}

double sharpness(const Cell& c) { return std::max(c.spreadX, c.spreadY); }

double leastSpread(const Grid& g) {
  double least = 0;
  for (const Cell& c : g.cells) {
    if (c.covered && (least == 0 || sharpness(c) < least)) least = sharpness(c);
  }
  return least;
}

// The exemplar: the longest run of cell columns where nearly every cell is at most
// `limit` times the least spread.
std::pair<int, int> sharpColumns(const Grid& g, int width, double least, double limit) {
  int best0 = 0, best1 = 0, run0 = -1;
  for (int cx = 0; cx <= g.cols; ++cx) {
    bool sharp = false;
    if (cx < g.cols) {
      int n = 0;
      for (int cy = 0; cy < g.rows; ++cy) {
        const Cell& c = g.at(cx, cy);
        n += c.covered && sharpness(c) <= limit * least;
      }
      sharp = n >= 0.5 * g.rows;
    }
    if (sharp && run0 < 0) run0 = cx;
    if (!sharp && run0 >= 0) {
      if (cx - run0 > best1 - best0) best0 = run0, best1 = cx;
      run0 = -1;
    }
  }
  return {best0 * kCell, std::min(width, best1 * kCell)};
}

// The sharp columns, kSharpSpread times the least spread; a wall the photo saw at a
// grazing angle is sharp over a few cells only, so the limit grows until the exemplar
// holds a few tiles (detail still goes only where the photo saw 1.4 times coarser).
constexpr int kMinExemplarColumns = 4 * kTile;
std::pair<int, int> exemplarColumns(const Grid& g, int width, double least) {
  std::pair<int, int> columns;
  for (double limit = kSharpSpread; limit <= 4 * kSharpSpread; limit *= 1.5) {
    columns = sharpColumns(g, width, least, limit);
    if (columns.second - columns.first >= std::min(kMinExemplarColumns, width / 4)) break;
  }
  return columns;
}

// The period along x of the exemplar's fine structure (texels, sub-texel), 0 when it
// does not repeat: the mean over rows of each row's autocorrelation, each row over the
// longest part of it the photo shows (at least half the exemplar).
double periodAlongX(const cv::Mat1f& lum, const cv::Mat1b& shown) {
  const int n = lum.cols;
  if (n < 24) return 0;
  cv::Mat1f smooth, hp;
  cv::GaussianBlur(lum, smooth, {0, 0}, 6.0);
  hp = lum - smooth;
  // Outliers (a dark band, a door frame) would swamp the pattern's own correlation.
  cv::Scalar m, sd;
  cv::meanStdDev(hp, m, sd, shown);
  cv::min(hp, 2.5 * sd[0], hp);
  cv::max(hp, -2.5 * sd[0], hp);
  const int padded = cv::getOptimalDFTSize(2 * n);
  cv::Mat1f rows = cv::Mat1f::zeros(lum.rows, padded);
  std::vector<int> lengths;
  int used = 0;
  for (int y = 0; y < lum.rows; ++y) {
    int best0 = 0, best1 = 0, run0 = -1;
    for (int x = 0; x <= n; ++x) {
      const bool on = x < n && shown(y, x);
      if (on && run0 < 0) run0 = x;
      if (!on && run0 >= 0) {
        if (x - run0 > best1 - best0) best0 = run0, best1 = x;
        run0 = -1;
      }
    }
    if (best1 - best0 < n / 2) continue;
    hp(cv::Rect(best0, y, best1 - best0, 1)).copyTo(rows(cv::Rect(0, used, best1 - best0, 1)));
    lengths.push_back(best1 - best0);
    ++used;
  }
  if (used < 4) return 0;
  rows = rows.rowRange(0, used).clone();
  cv::Mat spectrum;
  cv::dft(rows, spectrum, cv::DFT_ROWS | cv::DFT_COMPLEX_OUTPUT);
  cv::mulSpectrums(spectrum, spectrum, spectrum, cv::DFT_ROWS, true);
  cv::Mat1f acf;
  cv::dft(spectrum, acf, cv::DFT_ROWS | cv::DFT_INVERSE | cv::DFT_REAL_OUTPUT);
  std::vector<double> r(n, 0.0), overlap(n, 0.0);
  for (int y = 0; y < used; ++y) {
    for (int lag = 0; lag < lengths[y]; ++lag) r[lag] += acf(y, lag), overlap[lag] += lengths[y] - lag;
  }
  if (!(r[0] > 1e-6)) return 0;
  const double zero = r[0] / overlap[0];
  for (int lag = 0; lag < n; ++lag) r[lag] = overlap[lag] > 0 ? r[lag] / overlap[lag] / zero : 0.0;  // unbiased
  const int lo = 6, hi = n / 2;
  if (hi <= lo + 1) return 0;
  double best = 0;
  for (int lag = lo; lag < hi; ++lag) best = std::max(best, r[lag]);
  if (best < 0.4) return 0;
  // The peak nearest `lag` (within `reach`), to a fraction of a texel.
  const auto peakNear = [&](double lag, int reach) -> std::optional<double> {
    int at = -1;
    for (int l = std::max(1, static_cast<int>(std::lround(lag)) - reach);
         l <= std::min(n - 2, static_cast<int>(std::lround(lag)) + reach); ++l) {
      if (r[l] >= r[l - 1] && r[l] >= r[l + 1] && (at < 0 || r[l] > r[at])) at = l;
    }
    if (at < 0) return std::nullopt;
    const double a = r[at - 1], b = r[at], c = r[at + 1], d = a - 2 * b + c;
    return at + (std::abs(d) > 1e-12 ? 0.5 * (a - c) / d : 0.0);
  };
  // The fundamental: the first local maximum nearly as strong as the best.
  for (int lag = lo; lag < hi; ++lag) {
    if (r[lag] >= 0.85 * best && r[lag] >= r[lag - 1] && r[lag] >= r[lag + 1]) {
      double period = *peakNear(lag, 0);
      // Refined at its multiples, as far as the overlap leaves a clear peak: the error of
      // one peak's position is divided by the multiple, and a lattice continued for tens
      // of periods beyond the exemplar needs the period to a small fraction of a texel.
      for (int k = 2; k * period < 0.75 * n; ++k) {
        const auto peak = peakNear(k * period, std::max(1, static_cast<int>(0.15 * period)));
        if (!peak || r[static_cast<int>(std::lround(*peak))] < 0.5 * best) break;
        period = *peak / k;
      }
      return period;
    }
  }
  return 0;
}

// Half-octave blur levels, up to a spread of 16 texels (beyond, the photo kept the
// coarser bands itself, and wider blurs would cost more than they add).
int level(double spread) { return std::clamp(static_cast<int>(std::lround(2.0 * std::log2(std::max(1.0, spread)))), 0, 8); }
double spreadOfLevel(int q) { return std::pow(2.0, q / 2.0); }

// The exemplar blurred as the photo blurs a cell of spread (2^(qx/2), 2^(qy/2)), with
// the same shrunk by (kx, ky) for matching.
struct Blurred {
  cv::Mat1f blurred;  // the exemplar's luminance, blurred
  cv::Mat1f detail;   // the exemplar's luminance less its blur: what the photo lost there
  cv::Mat1f small;    // the blurred luminance, shrunk
  int kx = 1, ky = 1;
};

// The median spreads of the exemplar's cells: the blur it has itself.
glm::dvec2 exemplarSpread(const Grid& g, int x0, int x1) {
  std::vector<double> xs, ys;
  for (int cy = 0; cy < g.rows; ++cy) {
    for (int cx = x0 / kCell; cx < (x1 + kCell - 1) / kCell && cx < g.cols; ++cx) {
      if (g.at(cx, cy).covered) xs.push_back(g.at(cx, cy).spreadX), ys.push_back(g.at(cx, cy).spreadY);
    }
  }
  if (xs.empty()) return {1, 1};
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  std::nth_element(ys.begin(), ys.begin() + ys.size() / 2, ys.end());
  return {xs[xs.size() / 2], ys[ys.size() / 2]};
}

// Columns unlike the rest (a band, a door frame), from each column's mean: compared with
// the median of the columns whole periods away (of all columns when the surface does not
// repeat). They lend neither detail nor fill.
std::vector<bool> oddColumns(const std::vector<float>& means, double period) {
  const int n = static_cast<int>(means.size());
  const auto medianOf = [](std::vector<float> x) {
    std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
    return x[x.size() / 2];
  };
  std::vector<bool> odd(n, false);
  if (n == 0) return odd;
  std::vector<float> residual(n);
  for (int i = 0; i < n; ++i) {
    if (period <= 0) {  // against the columns around it (the light changes along a corridor)
      std::vector<float> around;
      for (int j = std::max(0, i - 48); j < std::min(n, i + 49); ++j) {
        if (std::abs(j - i) > 8 && means[j] > 0) around.push_back(means[j]);
      }
      residual[i] = around.empty() ? 0.0f : means[i] - medianOf(around);
      continue;
    }
    std::vector<float> same;
    for (double x = std::fmod(i, period); x < n; x += period) same.push_back(means[std::min(n - 1, static_cast<int>(std::lround(x)))]);
    residual[i] = means[i] - medianOf(same);
  }
  std::vector<float> dev;
  for (float r : residual) dev.push_back(std::abs(r));
  const float mad = std::max(1.0f, medianOf(dev));
  for (int i = 0; i < n; ++i) odd[i] = std::abs(residual[i]) > std::max(4 * mad, 12.0f);
  return odd;
}

// Each column's mean over the texels the photo shows (0 where it shows none).
std::vector<float> columnMeans(const cv::Mat1f& lum, const cv::Mat1b& shown) {
  std::vector<float> means(lum.cols, 0.0f);
  for (int x = 0; x < lum.cols; ++x) {
    double sum = 0;
    int count = 0;
    for (int y = 0; y < lum.rows; ++y) {
      if (shown(y, x)) sum += lum(y, x), ++count;
    }
    means[x] = count ? static_cast<float>(sum / count) : 0.0f;
  }
  return means;
}

// The detail, as the detail layer's codes (engine/scene/texture_detail.h): per texel,
// the ratio of the linear luminance with the matches' detail (luminance, sRGB-encoded,
// added to each channel) added to the texel's own. `lum`: the texture's luminance.
void addDetail(const cv::Mat3b& base, const cv::Mat1f& lum, const Grid& grid, int x0, int x1, double period,
               cv::Mat1b& codes, SynthesisStats& stats) {
  const int width = base.cols, height = base.rows;
  const int exemplarWidth = x1 - x0;
  if (exemplarWidth < kTile + 8 || height < kTile) return;
  const glm::dvec2 own = exemplarSpread(grid, x0, x1);
  const cv::Mat1f exemplarLum = lum(cv::Range::all(), cv::Range(x0, x1));
  cv::Mat1f means;
  cv::reduce(exemplarLum, means, 0, cv::REDUCE_AVG);
  const std::vector<bool> odd = oddColumns(std::vector<float>(means.begin(), means.end()), period);
  std::vector<int> oddBefore(exemplarWidth + 1, 0);  // prefix counts
  for (int i = 0; i < exemplarWidth; ++i) oddBefore[i + 1] = oddBefore[i] + odd[i];
  const auto clean = [&](int sx) { return oddBefore[sx + kTile] - oddBefore[sx] == 0; };
  std::map<std::pair<int, int>, Blurred> cache;
  const auto blurredFor = [&](int qx, int qy) -> const Blurred& {
    auto it = cache.find({qx, qy});
    if (it != cache.end()) return it->second;
    Blurred b;
    const double sx = spreadOfLevel(qx), sy = spreadOfLevel(qy);
    cv::Mat1f& l = b.blurred;
    cv::GaussianBlur(exemplarLum, l, {0, 0}, kBlurPerSpread * sx, kBlurPerSpread * sy, cv::BORDER_REFLECT);
    b.detail = exemplarLum - l;
    b.kx = std::max(2, static_cast<int>(sx / 2));
    b.ky = std::max(2, static_cast<int>(sy / 2));
    cv::resize(l, b.small, {std::max(1, l.cols / b.kx), std::max(1, l.rows / b.ky)}, 0, 0, cv::INTER_AREA);
    return cache.emplace(std::make_pair(qx, qy), std::move(b)).first->second;
  };

  // A coarse tile's luminance shrunk as the exemplar's is for matching.
  const auto shrunkTile = [&](const Blurred& b, int tx, int ty) {
    cv::Mat1f tile;
    cv::resize(lum(cv::Rect(tx, ty, kTile, kTile)), tile, {std::max(1, kTile / b.kx), std::max(1, kTile / b.ky)}, 0, 0,
               cv::INTER_AREA);
    return tile;
  };
  cv::Mat1f detail = cv::Mat1f::zeros(base.size());
  cv::Mat1f weight = cv::Mat1f::zeros(base.size());
  std::vector<float> window(kTile);
  for (int i = 0; i < kTile; ++i) window[i] = static_cast<float>(std::pow(std::sin(CV_PI * (i + 0.5) / kTile), 2));
  // Tiles from the exemplar outwards, so that a periodic surface's phase, corrected
  // where the evidence is clear, carries on to where it is not.
  std::vector<int> columns;
  for (int tx = 0; tx + kTile <= width; tx += std::min(kStride, std::max(1, width - kTile - tx))) {
    if (tx + kTile <= x0 || tx >= x1) columns.push_back(tx);
  }
  std::sort(columns.begin(), columns.end(), [&](int a, int b) {
    const auto d = [&](int t) { return t < x0 ? x0 - t : t - x1; };
    return d(a) < d(b);
  });
  const double centre = x0 + 0.5 * (exemplarWidth - kTile);
  for (int ty = 0; ty + kTile <= height; ty += std::min(kStride, std::max(1, height - kTile - ty))) {
    for (int tx : columns) {
      const Cell& c = grid.at(std::min(grid.cols - 1, (tx + kTile / 2) / kCell), std::min(grid.rows - 1, (ty + kTile / 2) / kCell));
      if (!c.covered || sharpness(c) < kCoarseSpread * std::max(own.x, own.y)) continue;
      // The blur the photo adds here beyond the exemplar's own.
      const int qx = level(std::sqrt(std::max(1.0, c.spreadX * c.spreadX - own.x * own.x)));
      const int qy = level(std::sqrt(std::max(1.0, c.spreadY * c.spreadY - own.y * own.y)));
      const Blurred& b = blurredFor(qx, qy);
      // Where to take the detail from. Periodic: the lattice continued, the same phase
      // whole periods away (the rectified plane is metric, so the period holds along
      // the whole surface; the coarse evidence was tried for the phase and moved it
      // off more often than on), to a fraction of a texel. Else: the exemplar's tile the
      // coarse one matches best, blurred as the photo blurred it.
      double sourceX;
      int sy = ty;
      double gain = kDetailGain;
      if (period > 0) {
        sourceX = tx - std::round((tx - centre) / period) * period - x0;
        const double last = exemplarWidth - kTile - 1.0;  // room for the sub-texel shift
        while (sourceX > last) sourceX -= period;
        while (sourceX < 0) sourceX += period;
        for (int k = 0; k < 4 && !clean(static_cast<int>(sourceX)); ++k) {  // whole periods away from odd columns
          if (sourceX + period <= last && clean(static_cast<int>(sourceX + period))) sourceX += period;
          else if (sourceX - period >= 0) sourceX -= period;
        }
        if (sourceX > last) continue;  // an exemplar shorter than a tile and a period
      } else {
        gain *= kRandomDetailGain;
        const int predicted = static_cast<int>((static_cast<unsigned>(tx) * 2654435761u + static_cast<unsigned>(ty) * 40503u) %
                                               static_cast<unsigned>(exemplarWidth - kTile));
        constexpr int kHalfWindow = 48;
        const int lo = std::clamp(predicted - kHalfWindow, 0, exemplarWidth - kTile);
        const int hi = std::clamp(predicted + kHalfWindow, lo, exemplarWidth - kTile);
        const int radius = std::clamp(static_cast<int>(std::lround(2 * spreadOfLevel(qy))), 2, 12);
        const int r0 = std::max(0, ty - radius), r1 = std::min(height, ty + kTile + radius);
        const cv::Mat1f tile = shrunkTile(b, tx, ty);
        const int sc0 = lo / b.kx, sc1 = std::min(b.small.cols, (hi + kTile) / b.kx);
        const int sr0 = r0 / b.ky, sr1 = std::min(b.small.rows, (r1 + b.ky - 1) / b.ky);
        cv::Scalar mean, stddev;
        cv::meanStdDev(tile, mean, stddev);
        sourceX = predicted;
        if (stddev[0] >= 0.75 && sr1 - sr0 >= tile.rows && sc1 - sc0 >= tile.cols) {
          cv::Mat1f score;
          cv::matchTemplate(b.small(cv::Range(sr0, sr1), cv::Range(sc0, sc1)), tile, score, cv::TM_CCOEFF_NORMED);
          double best;
          cv::Point at;
          cv::minMaxLoc(score, nullptr, &best, nullptr, &at);
          gain *= std::clamp((best - 0.3) / 0.4, 0.0, 1.0);
          sourceX = std::clamp((sc0 + at.x) * b.kx, 0, exemplarWidth - kTile);
          sy = std::clamp((sr0 + at.y) * b.ky, 0, height - kTile);
        }
        if (!clean(static_cast<int>(sourceX))) continue;
      }
      if (gain <= 0) continue;
      // The match's contrast against the tile's: shading differs along a corridor.
      const int sx = static_cast<int>(sourceX);
      cv::Scalar tileMean, tileStd, sourceMean, sourceStd;
      cv::meanStdDev(shrunkTile(b, tx, ty), tileMean, tileStd);
      cv::meanStdDev(b.blurred(cv::Rect(sx, sy, kTile, kTile)), sourceMean, sourceStd);
      const double contrast = sourceStd[0] > 0.5 && tileStd[0] >= 0.75 ? std::clamp(tileStd[0] / sourceStd[0], 0.5, 1.5) : 1.0;
      const float k = static_cast<float>(gain * contrast);
      cv::Mat1f patch;
      cv::getRectSubPix(b.detail, {kTile, kTile}, cv::Point2f(static_cast<float>(sourceX + 0.5 * (kTile - 1)),
                                                              static_cast<float>(sy + 0.5 * (kTile - 1))), patch);
      for (int y = 0; y < kTile; ++y) {
        const float* from = patch.ptr<float>(y);
        float* d = detail.ptr<float>(ty + y) + tx;
        float* w = weight.ptr<float>(ty + y) + tx;
        for (int x = 0; x < kTile; ++x) {
          const float wx = window[x] * window[y];
          d[x] += from[x] * (k * wx);
          w[x] += wx;
        }
      }
    }
  }
  int added = 0;
  codes.create(base.size());
  codes.setTo(engine::kNoDetail);
  // Linear light of an sRGB-encoded BGR texel (0..255) with `add` on each channel.
  const auto luminance = [](const cv::Vec3b& bgr, float add) {
    const auto lin = [add](uint8_t v) {
      return engine::linearOfSrgbByte(static_cast<uint8_t>(std::clamp(v + add + 0.5f, 0.0f, 255.0f)));
    };
    return 0.0722f * lin(bgr[0]) + 0.7152f * lin(bgr[1]) + 0.2126f * lin(bgr[2]);
  };
  for (int y = 0; y < height; ++y) {
    const cv::Vec3b* b = base.ptr<cv::Vec3b>(y);
    const float* d = detail.ptr<float>(y);
    const float* w = weight.ptr<float>(y);
    uint8_t* code = codes.ptr<uint8_t>(y);
    for (int x = 0; x < width; ++x) {
      if (w[x] <= 1e-3f) continue;
      const float own = luminance(b[x], 0.0f);
      if (!(own > 1e-4f)) continue;  // black: no ratio brightens it
      const float ratio = luminance(b[x], d[x] / std::max(w[x], 0.25f)) / own;
      code[x] = std::min(engine::detailCode(ratio), engine::detailCodeLimit(b[x].val));
      added += code[x] != engine::kNoDetail;
    }
  }
  stats.detailFraction = double(added) / (double(width) * height);
}

// Fills the texels the photo does not show from the shown ones in the same row.
// `sharpEnd`: where the exemplar ends; a mirrored fill reflects no further (the part the
// photo saw sharply, not the far end's blur).
void fill(cv::Mat3b& texture, const cv::Mat1f& lum, const cv::Mat1b& shown, double period, int sharpEnd,
          SynthesisStats& stats) {
  const int width = texture.cols, height = texture.rows;
  std::vector<float> means = columnMeans(lum, shown);
  std::vector<bool> odd = oddColumns(means, period);
  for (int x = 0; x < width; ++x) odd[x] = odd[x] && means[x] > 0;
  std::vector<int> first(height, -1), last(height, -1);
  for (int y = 0; y < height; ++y) {
    const uint8_t* m = shown.ptr<uint8_t>(y);
    for (int x = 0; x < width; ++x) {
      if (m[x]) {
        if (first[y] < 0) first[y] = x;
        last[y] = x;
      }
    }
  }
  // Rows the photo does not show at all borrow the nearest row it shows.
  std::vector<int> rowOf(height, -1);
  for (int y = 0; y < height; ++y) {
    for (int d = 0; d < height && rowOf[y] < 0; ++d) {
      if (y - d >= 0 && first[y - d] >= 0) rowOf[y] = y - d;
      else if (y + d < height && first[y + d] >= 0) rowOf[y] = y + d;
    }
  }
  int filled = 0;
  std::vector<int> good;  // the columns a mirrored fill reflects over, for `goodFor`
  std::pair<int, int> goodFor{-1, -1};
  for (int y = 0; y < height; ++y) {
    const int row = rowOf[y];
    if (row < 0) return;  // the photo shows nothing of this surface
    const int a = first[row], b = last[row], span = b - a + 1;
    const int mirrorSpan = std::max(1, std::min(b, std::max(a, sharpEnd - 1)) - a + 1);
    const cv::Vec3b* src = texture.ptr<cv::Vec3b>(row);
    cv::Vec3b* dst = texture.ptr<cv::Vec3b>(y);
    const uint8_t* m = shown.ptr<uint8_t>(y);
    const uint8_t* srcShown = shown.ptr<uint8_t>(row);
    for (int x = 0; x < width; ++x) {
      if (m[x] && row == y) continue;
      int sx;
      const bool periodic = period > 0 && span > period + 1;
      if (periodic) {
        // Whole periods towards the shown span: the lattice continues.
        const double n = x < a ? std::ceil((a - x) / period) : x > b ? -std::ceil((x - b) / period) : 0.0;
        sx = std::clamp(static_cast<int>(std::lround(x + n * period)), a, b);
        // Past odd columns by whole periods, further into the span.
        const int step = static_cast<int>(std::lround(period)) * (x < a ? 1 : -1);
        for (int k = 0; k < 16 && odd[sx] && sx + step >= a && sx + step <= b; ++k) sx += step;
      } else {
        // Mirrored into the shown span's columns that are not odd (no joins, no seam).
        const bool near = x < a;
        const int lo = near ? a : std::max(a, b - span + 1), hi = near ? a + mirrorSpan - 1 : b;
        if (goodFor != std::make_pair(lo, hi)) {
          good.clear();
          for (int c = lo; c <= hi; ++c) {
            if (!odd[c]) good.push_back(c);
          }
          if (good.empty()) good.push_back(near ? a : b);
          goodFor = {lo, hi};
        }
        const int n = static_cast<int>(good.size());
        const int offset = near ? a - 1 - x : x > b ? x - b - 1 : x - a;
        const int cycle = offset % (2 * n), i = cycle < n ? cycle : 2 * n - 1 - cycle;
        sx = near ? good[i] : good[n - 1 - i];
      }
      if (!srcShown[sx]) sx = x < a ? a : b;
      dst[x] = src[sx];
      ++filled;
    }
  }
  stats.filledFraction = double(filled) / (double(width) * height);
}

}  // namespace

SynthesisStats synthesizeSurface(cv::Mat& texture, const PhotoOfTexel& photoOf, cv::Size photoSize,
                                 const SynthesisOptions& options, cv::Mat* detail) {
  SynthesisStats stats;
  if (detail) detail->release();
  if (texture.empty() || texture.type() != CV_8UC3) return stats;
  const Grid grid = footprints(texture.size(), photoOf, photoSize);
  const double least = leastSpread(grid);
  const auto [x0, x1] = exemplarColumns(grid, texture.cols, least);
  const bool exemplar = x1 - x0 >= kTile;  // without one: no period, no detail, a mirrored fill
  stats.exemplarColumns = exemplar ? x1 - x0 : 0;
  cv::Mat3b pixels = texture;  // shares the caller's pixels: the fill copies in place
  cv::Mat1b grey;
  cv::cvtColor(pixels, grey, cv::COLOR_BGR2GRAY);
  cv::Mat1f lum;
  grey.convertTo(lum, CV_32F);
  const cv::Mat1b shown = coverage(texture.size(), photoOf, photoSize);
  const double period =
      exemplar ? periodAlongX(lum(cv::Range::all(), cv::Range(x0, x1)), shown(cv::Range::all(), cv::Range(x0, x1))) : 0.0;
  stats.periodPx = static_cast<int>(std::lround(period));
  // Filled first, so that the exemplar's own gaps hold texture before it lends detail.
  if (options.fill) {
    // The texels along the photo's border (within kBorderPx of it) lend nothing, but
    // they are the photo's own: filled over, the photo's camera saw synthesized texture
    // in the photo's outermost rows and columns (TUNE seed 36: 4.5 dB lower from the
    // photo's camera once a person stood up, because the fill there changed with her).
    const cv::Mat1b border = coverage(texture.size(), photoOf, photoSize, 0.0) & ~shown;
    const cv::Mat3b photoOwn = pixels.clone();
    fill(pixels, lum, shown, period, exemplar ? x1 : texture.cols, stats);
    photoOwn.copyTo(pixels, border);
  }
  if (options.detail && exemplar) {
    cv::Mat1f filledLum;
    cv::cvtColor(pixels, grey, cv::COLOR_BGR2GRAY);
    grey.convertTo(filledLum, CV_32F);
    cv::Mat1b codes;
    addDetail(pixels, filledLum, grid, x0, x1, period, codes, stats);
    if (stats.detailFraction > 0) {
      for (int y = 0; y < pixels.rows; ++y) {
        cv::Vec3b* p = pixels.ptr<cv::Vec3b>(y);
        const uint8_t* code = codes.ptr<uint8_t>(y);
        for (int x = 0; x < pixels.cols; ++x) {
          if (code[x] != engine::kNoDetail) engine::applyDetail(p[x].val, code[x], p[x].val);
        }
      }
      if (detail) *detail = codes;
    }
  }
  return stats;
}

}  // namespace pw::modeling
