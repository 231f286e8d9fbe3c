// nginx_server.h - a private nginx for the remote-cache tests and benchmark: Debian's nginx,
// WebDAV PUT on, run as a ServerProcess (server_process.h): one process in the foreground (no
// master/worker pair), its config, stored objects, logs, pid file and temporaries all under the
// folder the caller names.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "testsupport/local_port.h"
#include "testsupport/server_process.h"

namespace testsupport {

enum class NginxMode {
  webdav,  // GET and PUT under /cache/, PUT creating the folders it needs
  errors,  // every request answered 500 (a broken server behind a working socket)
};

// nginx on PATH, else Debian's /usr/sbin/nginx (not on a normal user's PATH); empty if neither.
std::filesystem::path find_nginx();

class NginxServer : public ServerProcess {
 public:
  // Starts the server under `root` (created; its old contents stay). running() says whether
  // it came up, error() why not.
  explicit NginxServer(const std::filesystem::path& root, NginxMode mode = NginxMode::webdav);

 private:
  std::string config_text(NginxMode mode, std::uint16_t port) const;
};

}  // namespace testsupport
