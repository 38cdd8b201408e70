// Configure-time probe (CMakeLists.txt): was the linked SimTKcommon built with NDEBUG?
// Compiled with -DNDEBUG, so no check of this file's own inline code remains; an
// exception can only come from the library's out-of-line MatrixHelper::getElt, which
// range-checks only when the library was built without NDEBUG. The out-of-range
// element's address is taken, never read.
#include <SimTKcommon.h>
#include <cstdio>
#include <exception>

int main() {
    SimTK::Vector v(4, 0.0);
    const SimTK::Vector& cv = v;
    try {
        const double* p = &cv[4];
        (void)p;
        std::puts("checks-off");
    } catch (const std::exception&) {
        std::puts("checks-on");
    }
    return 0;
}
