"""The projector (docs/class.md, "The projector"): its page (projector.html beside this file:
the join screen, a QR code of the phones' address with the address and the class code in large
type, then the class live from the event stream) and the QR code as SVG, made by segno
(python3-segno). The teacher's key is never in the QR code: it holds the phones' address only.
The local CA's certificate is served at /ca.pem for the phones that install it. The projector's
address of a class that is no more (ended, or deleted after --keep-days) is a page saying so and
what to do next, not the API's JSON."""
import html
import io
import pathlib

import segno
from aiohttp import web

PAGE = pathlib.Path(__file__).with_name("projector.html")
# The projector page loads nothing from any other host, and nothing but itself and this
# server's API: what the browser is told to refuse.
PAGE_POLICY = ("default-src 'none'; script-src 'self' 'unsafe-inline'; style-src 'unsafe-inline'; "
               "img-src 'self' data:; connect-src 'self'; base-uri 'none'; form-action 'none'; "
               "frame-ancestors 'none'")


GONE_PAGE = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>bookspin class: no class {code}</title>
<style>body {{ font: 28px/1.4 "DejaVu Sans", sans-serif; max-width: 40em; margin: 18vh auto;
padding: 0 1em; }} code {{ background: #f2f2f2; padding: 0.1em 0.3em; }}</style></head>
<body><p><strong>No class {code} here: it has ended and its data is deleted</strong> (or the
code is mistyped).</p><p>Start a new class with <code>build/bookspin-class --new</code> and open
the projector address it prints.</p></body></html>
"""


def qr_svg(text):
    """The QR code of `text` as an SVG document (error correction M, a 4-module quiet zone)."""
    out = io.BytesIO()
    segno.make(text, error="m", micro=False).save(out, kind="svg", scale=10, border=4,
                                                  dark="#000", light="#fff", xmldecl=False)
    return out.getvalue().decode("utf-8")


def add_routes(app, server):
    async def projector(request):
        code = request.query.get("class", "")
        if len(code) > 16 or not await server.db(server.store.class_exists, code):
            return web.Response(text=GONE_PAGE.format(code=html.escape(code[:16])), status=404,
                                content_type="text/html",
                                headers={"Content-Security-Policy": PAGE_POLICY})
        await server.teacher(request, code)
        return web.FileResponse(PAGE, headers={"Content-Security-Policy": PAGE_POLICY,
                                               "Cache-Control": "no-cache"})

    async def qr(request):
        code = await server.class_code(request)
        await server.teacher(request, code)
        return web.Response(text=qr_svg(server.join_url(code)), content_type="image/svg+xml")

    async def ca(request):
        if server.ca_file is None:
            raise web.HTTPNotFound()
        return web.Response(body=server.ca_file.read_bytes(),
                            content_type="application/x-x509-ca-cert",
                            headers={"Content-Disposition":
                                     'attachment; filename="bookspin-class-ca.crt"'})

    app.router.add_get("/projector", projector)
    app.router.add_get("/api/class/{code}/qr.svg", qr)
    app.router.add_get("/ca.pem", ca)
