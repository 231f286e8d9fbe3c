#include "testsupport/nginx_server.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace testsupport {

std::filesystem::path find_nginx() {
  if (const char* path = std::getenv("PATH")) {
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':'))
      if (!dir.empty() && ::access((std::filesystem::path(dir) / "nginx").c_str(), X_OK) == 0)
        return std::filesystem::path(dir) / "nginx";
  }
  if (::access("/usr/sbin/nginx", X_OK) == 0) return "/usr/sbin/nginx";
  return {};
}

NginxServer::NginxServer(const std::filesystem::path& root, NginxMode mode) : ServerProcess(root) {
  std::filesystem::path nginx = find_nginx();
  if (nginx.empty()) {
    set_error(
        "nginx is not installed (not on PATH, not /usr/sbin/nginx): the remote-cache tests need "
        "Debian's nginx package; scripts/install-deps.sh installs it");
    return;
  }
  for (const char* dir : {"data/cache", "tmp", "logs"}) std::filesystem::create_directories(this->root() / dir);
  start(nginx, "nginx", [&](std::uint16_t port) {
    const std::filesystem::path config = this->root() / "nginx.conf";
    std::ofstream(config) << config_text(mode, port);
    return std::vector<std::string>{"-p", this->root().string(), "-e", (this->root() / "logs" / "error.log").string(),
                                    "-c", config.string()};
  });
}

std::string NginxServer::config_text(NginxMode mode, std::uint16_t port) const {
  const std::string r = root().string();
  std::string location = mode == NginxMode::errors ? "      return 500;\n"
                                                   : "      dav_methods PUT;\n"
                                                     "      create_full_put_path on;\n"
                                                     "      client_max_body_size 0;\n";
  // Every path nginx would otherwise take from /var or /run is named here.
  return "daemon off;\nmaster_process off;\nerror_log " + r + "/logs/error.log warn;\npid " + r +
         "/nginx.pid;\nevents { worker_connections 256; }\nhttp {\n  access_log " + r +
         "/logs/access.log;\n  client_body_temp_path " + r + "/tmp/body;\n  proxy_temp_path " + r +
         "/tmp/proxy;\n  fastcgi_temp_path " + r + "/tmp/fastcgi;\n  uwsgi_temp_path " + r +
         "/tmp/uwsgi;\n  scgi_temp_path " + r + "/tmp/scgi;\n  server {\n    listen 127.0.0.1:" + std::to_string(port) +
         ";\n    root " + r + "/data;\n    location /cache/ {\n" + location + "    }\n  }\n}\n";
}

}  // namespace testsupport
