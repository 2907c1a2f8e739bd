"""A local web page where students check their answers before they submit them.

Contents:
    make_server(bank=, assignment=, host=, port=, log_path=)   the server; the caller runs serve_forever
    SelfCheckServer                                            what make_server returns (``.url``)
    problem_views, render_page                                 the page, built from an allow-list of fields
    workers.CheckPool                                          the processes that check answers

Built on the standard library's ``http.server``; the page is one HTML document with inline CSS
and script, and fetches nothing from the network. Reference answers never leave the server.
"""

from grader.serve.app import LIMITS, SelfCheckServer, make_server
from grader.serve.page import problem_views, render_page

__all__ = ["LIMITS", "SelfCheckServer", "make_server", "problem_views", "render_page"]
