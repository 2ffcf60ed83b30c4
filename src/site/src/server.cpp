// The loopback file server of `knots serve` (server.hpp).
#include "ek/site/server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>

#include "ek/core/errors.hpp"

namespace ek {
namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

/// Percent-decodes; false for a malformed escape.
bool percent_decode(const std::string& in, std::string& out) {
  out.clear();
  for (size_t i = 0; i < in.size(); ++i) {
    if (in[i] != '%') {
      out += in[i];
      continue;
    }
    if (i + 2 >= in.size()) return false;
    const int hi = hex_value(in[i + 1]), lo = hex_value(in[i + 2]);
    if (hi < 0 || lo < 0) return false;
    out += static_cast<char>(hi * 16 + lo);
    i += 2;
  }
  return true;
}

HttpResponse text(int status, const std::string& reason, const std::string& message) {
  return {status, reason, "text/plain; charset=utf-8", message + "\n"};
}

void send_all(int fd, const std::string& data) {
  size_t sent = 0;
  while (sent < data.size()) {
    const ssize_t k = ::send(fd, data.data() + sent, data.size() - sent, MSG_NOSIGNAL);
    if (k <= 0) return;  // the client went away or timed out
    sent += static_cast<size_t>(k);
  }
}

}  // namespace

HttpResponse respond(const SiteFiles& files, const std::string& method, const std::string& target) {
  if (method != "GET" && method != "HEAD") return text(405, "Method Not Allowed", "only GET and HEAD");
  if (target.empty() || target.front() != '/') return text(400, "Bad Request", "the target must start with /");
  std::string path = target.substr(0, target.find_first_of("?#"));
  std::string decoded;
  if (!percent_decode(path, decoded)) return text(400, "Bad Request", "malformed percent escape");
  if (decoded.find('\0') != std::string::npos || decoded.find('\\') != std::string::npos)
    return text(403, "Forbidden", "refused");
  std::string rel;
  std::stringstream segments(decoded.substr(1));
  for (std::string seg; std::getline(segments, seg, '/');) {
    if (seg == ".." || seg == ".") return text(403, "Forbidden", "refused: the path leaves the site");
    if (seg.empty()) continue;
    rel += (rel.empty() ? "" : "/") + seg;
  }
  if (rel.empty() || decoded.back() == '/') rel += (rel.empty() ? "" : "/") + std::string("index.html");
  const auto it = files.find(rel);
  if (it == files.end()) return text(404, "Not Found", "not a file of this site");
  return {200, "OK", content_type(rel), it->second};
}

std::string http_message(const HttpResponse& r, bool head_only) {
  std::string out = "HTTP/1.1 " + std::to_string(r.status) + " " + r.reason + "\r\n";
  out += "Content-Type: " + r.content_type + "\r\n";
  out += "Content-Length: " + std::to_string(r.body.size()) + "\r\n";
  out += "Cache-Control: no-cache\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n";
  if (r.status == 405) out += "Allow: GET, HEAD\r\n";
  out += "\r\n";
  if (!head_only) out += r.body;
  return out;
}

SiteServer::SiteServer(SiteFiles files, const ServeOptions& options) : files_(std::move(files)), options_(options) {
  if (options.port < 0 || options.port > 65535) throw InputError("--port must be in 0..65535");
  require(options.workers >= 1 && options.timeout_seconds >= 1, "SiteServer: workers and timeout must be >= 1");
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listen_fd_ < 0) throw InputError(std::string("cannot open a socket: ") + std::strerror(errno));
  const int one = 1;
  ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = htons(static_cast<uint16_t>(options.port));
  if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(listen_fd_, 64) != 0) {
    const std::string why = std::strerror(errno);
    ::close(listen_fd_);
    throw InputError("cannot listen on 127.0.0.1:" + std::to_string(options.port) + ": " + why +
                     " (choose another --port, or 0 for any free port)");
  }
  socklen_t len = sizeof addr;
  ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  port_ = ntohs(addr.sin_port);
  for (int i = 0; i < options.workers; ++i) threads_.emplace_back([this] { worker(); });
}

SiteServer::~SiteServer() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  ready_.notify_all();
  for (auto& t : threads_) t.join();
  for (int fd : queue_) ::close(fd);
  if (listen_fd_ >= 0) ::close(listen_fd_);
}

void SiteServer::serve(const std::atomic<bool>& stop) {
  while (!stop.load()) {
    pollfd p{listen_fd_, POLLIN, 0};
    if (::poll(&p, 1, 200) <= 0) continue;
    const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd < 0) continue;
    const timeval tv{options_.timeout_seconds, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      queue_.push_back(fd);
    }
    ready_.notify_one();
  }
}

void SiteServer::worker() {
  for (;;) {
    int fd = -1;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      ready_.wait(lock, [this] { return closing_ || !queue_.empty(); });
      if (closing_) return;
      fd = queue_.front();
      queue_.pop_front();
    }
    handle(fd);
    ::close(fd);
  }
}

void SiteServer::handle(int fd) {
  std::string head;
  char buf[4096];
  while (head.find("\r\n\r\n") == std::string::npos) {
    if (head.size() > options_.max_request) {
      send_all(fd, http_message(text(431, "Request Header Fields Too Large", "request too long"), false));
      return;
    }
    const ssize_t k = ::recv(fd, buf, sizeof buf, 0);
    if (k <= 0) return;  // closed or timed out
    head.append(buf, static_cast<size_t>(k));
  }
  std::istringstream line(head.substr(0, head.find("\r\n")));
  std::string method, target, version;
  line >> method >> target >> version;
  if (version.rfind("HTTP/", 0) != 0) {
    send_all(fd, http_message(text(400, "Bad Request", "malformed request line"), false));
    return;
  }
  send_all(fd, http_message(respond(files_, method, target), method == "HEAD"));
}

}  // namespace ek
