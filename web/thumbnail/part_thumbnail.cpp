#include "web/thumbnail/part_thumbnail.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <stdexcept>

namespace cadnurbs {

namespace {

using Eigen::Vector3d;

constexpr double kFieldOfView = 35.0 * M_PI / 180.0;  // vertical, as the viewer's camera
constexpr double kAmbient = 0.35;                      // light every face gets, facing the light or not

// The viewer's camera after fit(): the bounding sphere (centre of the box, radius to the farthest vertex)
// just inside the vertical field of view.
struct Camera {
  Vector3d eye, right, up, forward;
  double tan_half = 0, aspect = 1;
};

Camera fitted_camera(const std::vector<double>& positions, double aspect) {
  Vector3d low = Vector3d::Constant(INFINITY), high = Vector3d::Constant(-INFINITY);
  const size_t vertices = positions.size() / 3;
  for (size_t v = 0; v < vertices; ++v) {
    const Vector3d p(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const Vector3d centre = (low + high) / 2;
  double radius = 0;
  for (size_t v = 0; v < vertices; ++v)
    radius = std::max(radius, (Vector3d(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]) - centre).norm());
  if (!(radius > 0)) radius = 1;
  Camera camera;
  camera.tan_half = std::tan(kFieldOfView / 2);
  camera.aspect = aspect;
  const Vector3d direction = Vector3d(1, -1.4, 0.9).normalized();
  camera.eye = centre + direction * (radius / std::sin(kFieldOfView / 2));
  camera.forward = -direction;
  camera.right = camera.forward.cross(Vector3d::UnitZ()).normalized();
  camera.up = camera.right.cross(camera.forward);
  return camera;
}

// A vertex on the picture: pixel coordinates and the reciprocal of its depth (linear across a triangle
// on the screen, so that the depth test may interpolate it).
struct ScreenPoint {
  double x = 0, y = 0, inverse_depth = 0;
};

// The palette of the picture's colours, one entry per colour met; once 256 are met, a new colour takes the
// nearest entry.
struct Palette {
  std::map<uint32_t, uint8_t> index_of;
  std::vector<uint8_t> rgb;
  uint8_t index(uint8_t r, uint8_t g, uint8_t b) {
    const uint32_t key = uint32_t(r) << 16 | uint32_t(g) << 8 | b;
    const auto found = index_of.find(key);
    if (found != index_of.end()) return found->second;
    if (rgb.size() / 3 == 256) {
      int best = 0, best_distance = INT32_MAX;
      for (int c = 0; c < 256; ++c) {
        const int dr = rgb[3 * c] - r, dg = rgb[3 * c + 1] - g, db = rgb[3 * c + 2] - b;
        if (dr * dr + dg * dg + db * db < best_distance) best = c, best_distance = dr * dr + dg * dg + db * db;
      }
      return static_cast<uint8_t>(best);
    }
    const auto next = static_cast<uint8_t>(rgb.size() / 3);
    rgb.insert(rgb.end(), {r, g, b});
    index_of.emplace(key, next);
    return next;
  }
};

uint8_t channel(double value) { return static_cast<uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255)); }

}  // namespace

IndexedImage part_thumbnail(const SceneArrays& mesh, int width, int height) {
  if (width < 1 || height < 1) throw std::invalid_argument("part_thumbnail: the picture needs at least one pixel");
  IndexedImage image;
  image.width = width;
  image.height = height;
  image.pixels.assign(static_cast<size_t>(width) * height, 0);
  Palette palette;
  palette.index(255, 255, 255);  // the background is entry 0
  const size_t vertices = mesh.positions.size() / 3;
  if (vertices == 0 || mesh.indices.empty()) {
    image.palette = palette.rgb;
    return image;
  }
  const Camera camera = fitted_camera(mesh.positions, static_cast<double>(width) / height);
  const Vector3d light = (camera.right + camera.up - 2 * camera.forward).normalized();  // the viewer's (1, 1, 2)

  std::vector<ScreenPoint> screen(vertices);
  for (size_t v = 0; v < vertices; ++v) {
    const Vector3d q = Vector3d(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]) - camera.eye;
    const double depth = q.dot(camera.forward);  // positive: the camera is outside the bounding sphere
    const double sx = q.dot(camera.right) / (depth * camera.tan_half * camera.aspect);
    const double sy = q.dot(camera.up) / (depth * camera.tan_half);
    screen[v] = {(sx + 1) / 2 * width, (1 - sy) / 2 * height, 1 / depth};
  }

  // Few colours: thumbnail_shades shades of each face colour, the colour itself in steps of 1/16.
  std::vector<double> nearest(static_cast<size_t>(width) * height, 0);  // the largest 1/depth drawn per pixel
  const size_t faces = mesh.face_colours.size() / 3;
  for (size_t f = 0; f < faces; ++f) {
    double colour[3];
    for (int k = 0; k < 3; ++k) colour[k] = std::round(mesh.face_colours[3 * f + k] * 16) / 16;
    for (uint32_t t = mesh.face_first_triangle[f]; t < mesh.face_first_triangle[f + 1]; ++t) {
      const uint32_t* corner = &mesh.indices[3 * static_cast<size_t>(t)];
      auto world = [&](uint32_t v) { return Vector3d(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]); };
      const Vector3d normal = (world(corner[1]) - world(corner[0])).cross(world(corner[2]) - world(corner[0]));
      if (!(normal.norm() > 0)) continue;
      const double lit = std::abs(normal.normalized().dot(light));  // both sides lit, as the viewer's DoubleSide
      const double shade = std::round((kAmbient + (1 - kAmbient) * lit) * (thumbnail_shades - 1)) / (thumbnail_shades - 1);
      const uint8_t index = palette.index(channel(colour[0] * shade), channel(colour[1] * shade), channel(colour[2] * shade));
      const ScreenPoint &a = screen[corner[0]], &b = screen[corner[1]], &c = screen[corner[2]];
      const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      if (area == 0) continue;
      const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
      const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
      const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
      const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const double px = x + 0.5, py = y + 0.5;  // pixel centres
          const double wa = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
          const double wb = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
          const double wc = 1 - wa - wb;
          if (wa < 0 || wb < 0 || wc < 0) continue;
          const double inverse_depth = wa * a.inverse_depth + wb * b.inverse_depth + wc * c.inverse_depth;
          const size_t pixel = static_cast<size_t>(y) * width + x;
          if (inverse_depth <= nearest[pixel]) continue;
          nearest[pixel] = inverse_depth;
          image.pixels[pixel] = index;
        }
    }
  }
  image.palette = palette.rgb;
  return image;
}

}  // namespace cadnurbs
