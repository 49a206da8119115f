#pragma once
// A chapter's 3D pages (web_page.hpp) as its other outputs: written unless --no-plot or
// --no-viewer, said in one line, listed in the JSON summary under "pages".
#include <filesystem>

#include <kit/app/chapter_app.hpp>
#include <kit/render/web_page.hpp>

namespace kit {

/// Writes `page` to `path` (write_web_page) unless the flags say no page, prints its note and
/// records it in the summary as pages.<stem>: path, bytes, frames, frames_given, seconds,
/// position_error [m]. Returns what was written (empty path: nothing).
PageWritten write_page(ChapterApp& app, const WebPage& page, const std::filesystem::path& path);

}  // namespace kit
