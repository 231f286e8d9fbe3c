#include "testsupport/apache_server.h"

#include <unistd.h>

#include <fstream>
#include <vector>

namespace testsupport {

std::filesystem::path find_apache() {
  for (const char* path : {"/usr/sbin/apache2", "/usr/sbin/httpd"})
    if (::access(path, X_OK) == 0) return path;
  return {};
}

ApacheServer::ApacheServer(const std::filesystem::path& root) : ServerProcess(root) {
  std::filesystem::path apache = find_apache();
  if (apache.empty()) {
    set_error(
        "apache2 is not installed (/usr/sbin/apache2): the remote-cache tests need Debian's apache2 "
        "package; scripts/install-deps.sh --tests installs it");
    return;
  }
  for (const char* dir : {"data/cache", "logs", "lock"}) {
    std::filesystem::create_directories(this->root() / dir);
    std::filesystem::permissions(this->root() / dir, std::filesystem::perms::all);
  }
  start(apache, "apache2", [&](std::uint16_t port) {
    const std::filesystem::path config = this->root() / "apache2.conf";
    std::ofstream(config) << config_text(port);
    return std::vector<std::string>{"-X", "-f", config.string()};
  });
}

std::string ApacheServer::config_text(std::uint16_t port) const {
  const std::string r = root().string(), modules = "/usr/lib/apache2/modules/";
  std::string text;
  for (const char* module : {"mpm_prefork", "authz_core", "dav", "dav_fs"})
    text += "LoadModule " + std::string(module) + "_module " + modules + "mod_" + module + ".so\n";
  if (::geteuid() == 0) text += "User nobody\nGroup nogroup\n";
  // Every path Apache would otherwise take from /etc, /var or /run is named here.
  return text + "ServerName 127.0.0.1\nListen 127.0.0.1:" + std::to_string(port) + "\nPidFile " + r +
         "/apache2.pid\nMutex file:" + r + "/lock\nErrorLog " + r + "/logs/error.log\nLogFormat \"%r %>s\" plain\n" +
         "CustomLog " + r + "/logs/access.log plain\nDavLockDB " + r + "/lock/davlock\nDocumentRoot " + r +
         "/data\n<Directory " + r + "/data>\n  Require all granted\n</Directory>\n<Location /cache>\n  Dav On\n" +
         "</Location>\n";
}

}  // namespace testsupport
