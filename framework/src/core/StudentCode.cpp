#include <stoa/core/StudentCode.hpp>

namespace stoa {

StudentCode& studentCode() {
    static StudentCode table;
    return table;
}

} // namespace stoa
