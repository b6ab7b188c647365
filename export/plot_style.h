// The look of polarform's plots in one place: fonts, sizes, line widths, greys and the
// colour-blind-safe categorical palette of Okabe & Ito (2008), shared by the layout (plot_layout)
// and the drawing code (plot_panel, plot_legend). Sizes are in SVG pixels.
#pragma once

#include <array>
#include <string_view>

namespace polarform::plot_style {

inline constexpr std::string_view font_family = "DejaVu Sans, Helvetica, Arial, sans-serif";
inline constexpr double tick_font = 12;
inline constexpr double label_font = 13;
inline constexpr double title_font = 14;
inline constexpr double figure_title_font = 16;
inline constexpr double legend_font = 12;
inline constexpr double note_font = 10.5;  // reference-line labels, annotations, ×10ⁿ factors

inline constexpr double tick_length = 5;
inline constexpr double minor_tick_length = 3;
inline constexpr double line_width = 1.75;
inline constexpr double reference_width = 1.1;
inline constexpr double marker_radius = 3.5;
inline constexpr double band_opacity = 0.18;
inline constexpr double highlight_radius = 6;
inline constexpr double halo_width = 3;  // white outline that keeps notes legible over data
inline constexpr std::string_view dash = "6 4";
inline constexpr std::string_view reference_dash = "4 3";

inline constexpr std::string_view text_color = "#222222";
inline constexpr std::string_view frame_color = "#4d4d4d";
inline constexpr std::string_view grid_color = "#e2e2e2";
inline constexpr std::string_view minor_grid_color = "#f1f1f1";
inline constexpr std::string_view muted_text_color = "#888888";
inline constexpr std::string_view reference_color = "#666666";
inline constexpr std::string_view band_color = "#999999";
inline constexpr std::string_view highlight_color = "#D55E00";  // discontinuities, violations

// Okabe & Ito 2008, without the yellow that is unreadable on white.
inline constexpr std::array<std::string_view, 7> palette = {
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"};

}  // namespace polarform::plot_style
