// Chapter 5 end to end.
#include <catch2/catch.hpp>
