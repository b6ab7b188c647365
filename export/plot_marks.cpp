#include "export/plot_marks.h"

#include "export/svg_writer.h"

namespace polarform {

namespace {

std::string point(double x, double y) { return svg_number(x) + " " + svg_number(y); }

}  // namespace

MarkerShape marker_shape(int index) { return static_cast<MarkerShape>(index % 4); }

std::string marker_path(MarkerShape shape, PixelPoint c, double r) {
  switch (shape) {
    case MarkerShape::circle:
      return "M" + point(c.x - r, c.y) + "a" + point(r, r) + " 0 1 0 " + point(2 * r, 0) + "a" +
             point(r, r) + " 0 1 0 " + point(-2 * r, 0) + "Z";
    case MarkerShape::square: {
      const double h = 0.9 * r;  // a square of equal visual weight to the circle
      return "M" + point(c.x - h, c.y - h) + "H" + svg_number(c.x + h) + "V" + svg_number(c.y + h) +
             "H" + svg_number(c.x - h) + "Z";
    }
    case MarkerShape::triangle: {
      const double h = 1.2 * r;
      return "M" + point(c.x, c.y - h) + "L" + point(c.x + 0.866 * h, c.y + 0.5 * h) + "L" +
             point(c.x - 0.866 * h, c.y + 0.5 * h) + "Z";
    }
    case MarkerShape::diamond: {
      const double h = 1.25 * r;
      return "M" + point(c.x, c.y - h) + "L" + point(c.x + h, c.y) + "L" + point(c.x, c.y + h) +
             "L" + point(c.x - h, c.y) + "Z";
    }
  }
  return {};
}

}  // namespace polarform
