// local_port.h - TCP ports on 127.0.0.1 for the servers the tests and benchmarks start.
#pragma once

#include <cstdint>

namespace testsupport {

// A port on 127.0.0.1 that was free a moment ago: bound with port 0, read back, closed. Nobody
// listens on it until someone binds it again, so it also serves as "a closed port". 0 if no
// socket could be bound.
std::uint16_t unused_local_port();

// Whether something accepts a TCP connection on 127.0.0.1:`port` now.
bool accepts_connections(std::uint16_t port);

}  // namespace testsupport
