// The translation unit that precompiles grading_pch.hpp (tests/CMakeLists.txt): it defines nothing.
