// The test support library is header-first; this unit anchors the static library.
#include "support/golden.hpp"
