#pragma once
// The player's script and style (common/web/player.js, player.css), compiled into the library
// by CMake (web_assets.cpp.in) so that a chapter binary writes its pages wherever it runs.
namespace kit {
extern const char* const web_player_js;
extern const char* const web_player_css;
}  // namespace kit
