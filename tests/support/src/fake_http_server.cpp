#include "testsupport/fake_http_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <utility>

namespace testsupport {
namespace {

bool read_more(int fd, std::string& data) {
  char buffer[16384];
  ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
  if (n <= 0) return false;
  data.append(buffer, static_cast<std::size_t>(n));
  return true;
}

// The request line, the headers and a Content-Length body; false on a closed connection.
bool read_request(int fd, FakeRequest& request) {
  std::string data;
  std::size_t end = std::string::npos;
  while ((end = data.find("\r\n\r\n")) == std::string::npos)
    if (!read_more(fd, data)) return false;
  std::size_t line_end = data.find("\r\n");
  std::string line = data.substr(0, line_end);
  std::size_t space = line.find(' ');
  request.method = line.substr(0, space);
  request.path = line.substr(space + 1, line.find(' ', space + 1) - space - 1);
  for (std::size_t at = line_end + 2; at < end;) {
    std::size_t next = data.find("\r\n", at);
    std::string header = data.substr(at, next - at);
    std::size_t colon = header.find(':');
    std::string name = header.substr(0, colon);
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::size_t value = header.find_first_not_of(' ', colon + 1);
    request.headers[name] = value == std::string::npos ? "" : header.substr(value);
    at = next + 2;
  }
  std::size_t length = request.headers.count("content-length") ? std::stoul(request.headers["content-length"]) : 0;
  request.body = data.substr(end + 4);
  while (request.body.size() < length)
    if (!read_more(fd, request.body)) return false;
  return true;
}

}  // namespace

FakeHttpServer::FakeHttpServer(Handler handler) : handler_(std::move(handler)) {
  listener_ = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t size = sizeof address;
  if (listener_ < 0 || ::bind(listener_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(listener_, 64) != 0 || ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &size) != 0)
    return;
  port_ = ntohs(address.sin_port);
  acceptor_ = std::thread([this] { accept_loop(); });
}

FakeHttpServer::~FakeHttpServer() {
  stopping_ = true;
  ::shutdown(listener_, SHUT_RDWR);  // wakes accept()
  if (acceptor_.joinable()) acceptor_.join();
  ::close(listener_);
  std::lock_guard lock(mutex_);
  for (std::thread& t : connections_) t.join();
}

std::vector<FakeRequest> FakeHttpServer::requests() const {
  std::lock_guard lock(mutex_);
  return requests_;
}

void FakeHttpServer::accept_loop() {
  while (!stopping_) {
    int fd = ::accept(listener_, nullptr, nullptr);
    if (fd < 0) {
      if (stopping_) return;
      continue;
    }
    std::lock_guard lock(mutex_);
    connections_.emplace_back([this, fd] { serve(fd); });
  }
}

void FakeHttpServer::serve(int fd) {
  FakeRequest request;
  if (read_request(fd, request)) {
    {
      std::lock_guard lock(mutex_);
      requests_.push_back(request);
    }
    FakeReply reply = handler_(request);
    std::this_thread::sleep_for(reply.delay);
    std::string text = "HTTP/1.1 " + std::to_string(reply.status) +
                       " Fake\r\nContent-Length: " + std::to_string(request.method == "HEAD" ? 0 : reply.body.size()) +
                       "\r\nConnection: close\r\n\r\n" + (request.method == "HEAD" ? "" : reply.body);
    for (std::size_t sent = 0; sent < text.size();) {
      ssize_t n = ::send(fd, text.data() + sent, text.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) break;
      sent += static_cast<std::size_t>(n);
    }
  }
  ::close(fd);
}

}  // namespace testsupport
