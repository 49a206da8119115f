// The translation unit that precompiles test_pch.hpp (tests/CMakeLists.txt): it defines nothing.
