"""A local HTTP server speaking the slice of the GitHub REST API (issue comments) and the GitLab
REST API (merge request notes) that ci/pr-comment uses, so the templates' comment step runs its
real curl requests in the tests. It keeps the comments in memory and records every request.
"""
import http.server
import json
import re
import threading
import urllib.parse

GITHUB_LIST = re.compile(r'^/repos/([^/]+/[^/]+)/issues/(\d+)/comments$')
GITHUB_ONE = re.compile(r'^/repos/([^/]+/[^/]+)/issues/comments/(\d+)$')
GITLAB_LIST = re.compile(r'^/api/v4/projects/(\d+)/merge_requests/(\d+)/notes$')
GITLAB_ONE = re.compile(r'^/api/v4/projects/(\d+)/merge_requests/(\d+)/notes/(\d+)$')


class Forge:
    def __init__(self, token):
        self.token = token
        self.comments = {}   # thread (PR/MR number as text) -> [{"id", "body"}]
        self.requests = []   # (method, path)
        self.next_id = 1000
        self.server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), self.handler())
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)

    @property
    def url(self):
        return f"http://127.0.0.1:{self.server.server_address[1]}"

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.server.shutdown()

    def handler(self):
        forge = self

        class Handler(http.server.BaseHTTPRequestHandler):
            def log_message(self, *args):
                pass

            def reply(self, code, payload):
                data = json.dumps(payload).encode()
                self.send_response(code)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)

            def authorized(self):
                ok = self.headers.get("Authorization") == f"Bearer {forge.token}" or \
                    self.headers.get("PRIVATE-TOKEN") == forge.token
                if not ok:
                    self.reply(401, {"message": "Bad credentials"})
                return ok

            def body(self):
                return json.loads(self.rfile.read(int(self.headers.get("Content-Length", 0))))["body"]

            def route(self, method):
                url = urllib.parse.urlsplit(self.path)
                forge.requests.append((method, url.path))
                if not self.authorized():
                    return
                query = urllib.parse.parse_qs(url.query)
                thread_match = GITHUB_LIST.match(url.path) or GITLAB_LIST.match(url.path)
                one_match = GITHUB_ONE.match(url.path) or GITLAB_ONE.match(url.path)
                if thread_match and method == "GET":
                    page, per_page = int(query.get("page", ["1"])[0]), int(query.get("per_page", ["30"])[0])
                    items = forge.comments.get(thread_match.group(2), [])
                    return self.reply(200, items[(page - 1) * per_page: page * per_page])
                if thread_match and method == "POST":
                    forge.next_id += 1
                    item = {"id": forge.next_id, "body": self.body()}
                    forge.comments.setdefault(thread_match.group(2), []).append(item)
                    return self.reply(201, item)
                if one_match and method in ("PATCH", "PUT"):
                    wanted = int(one_match.groups()[-1])
                    for items in forge.comments.values():
                        for item in items:
                            if item["id"] == wanted:
                                item["body"] = self.body()
                                return self.reply(200, item)
                return self.reply(404, {"message": "Not Found"})

            def do_GET(self):
                self.route("GET")

            def do_POST(self):
                self.route("POST")

            def do_PATCH(self):
                self.route("PATCH")

            def do_PUT(self):
                self.route("PUT")

        return Handler
