// apache_server.h - a private Apache httpd for the remote-cache tests: Debian's apache2 with
// mod_dav (WebDAV PUT and MKCOL; a PUT into a missing collection is refused with 409, unlike
// nginx with create_full_put_path), run as a ServerProcess (server_process.h) with -X: one
// process in the foreground, its config, stored objects, lock database, logs and pid file under
// the folder the caller names.
//
// Run as root, Apache drops to the user "nobody" (it refuses to serve as root), so its folders
// are made writable by everyone.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "testsupport/server_process.h"

namespace testsupport {

// Debian's /usr/sbin/apache2 (or /usr/sbin/httpd); empty if neither.
std::filesystem::path find_apache();

class ApacheServer : public ServerProcess {
 public:
  explicit ApacheServer(const std::filesystem::path& root);

 private:
  std::string config_text(std::uint16_t port) const;
};

}  // namespace testsupport
