#include <kit/render/contact_sheet.hpp>

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace kit {

Image contact_sheet(const std::vector<Image>& frames, int columns, int gap_px) {
  if (frames.empty() || columns < 1 || gap_px < 0)
    throw std::invalid_argument(
        fmt::format("contact_sheet needs frames, columns >= 1 and gap >= 0 ({} frames, "
                    "{} columns, gap {})",
                    frames.size(), columns, gap_px));
  const int count = static_cast<int>(frames.size());
  const int used_columns = std::min(columns, count);
  const int rows = (count + used_columns - 1) / used_columns;
  int cell_width = 0, cell_height = 0;
  for (const Image& frame : frames)
    cell_width = std::max(cell_width, frame.width), cell_height = std::max(cell_height, frame.height);
  Image sheet(used_columns * cell_width + (used_columns + 1) * gap_px,
              rows * cell_height + (rows + 1) * gap_px, contact_sheet_background);
  for (int n = 0; n < count; ++n) {
    const Image& frame = frames[static_cast<std::size_t>(n)];
    const int left = gap_px + (n % used_columns) * (cell_width + gap_px);
    const int top = gap_px + (n / used_columns) * (cell_height + gap_px);
    for (int y = 0; y < frame.height; ++y)
      std::copy_n(frame.pixel(0, y), 3 * static_cast<std::size_t>(frame.width), sheet.pixel(left, top + y));
  }
  return sheet;
}

}  // namespace kit
