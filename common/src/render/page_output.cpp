// A chapter's 3D pages as its other outputs (page_output.hpp).
#include <kit/render/page_output.hpp>

#include <nlohmann/json.hpp>

#include <kit/app/report.hpp>

namespace kit {

PageWritten write_page(ChapterApp& app, const WebPage& page, const std::filesystem::path& path) {
  if (app.options().no_plot || app.options().no_viewer) return {};
  const PageWritten made = write_web_page(page, path);
  app.report().print(made.note + "\n");
  if (made.path.empty()) return made;
  app.summary()["pages"][path.stem().string()] = {
      {"path", made.path.string()}, {"bytes", made.bytes},
      {"frames", made.frames},      {"frames_given", made.frames_given},
      {"seconds", made.seconds},    {"position_error", made.position_error}};
  return made;
}

}  // namespace kit
