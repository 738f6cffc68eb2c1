"""WeasyPrint's SVG drawing without its repeated work: the same PDF operators, fewer times computed.

The report's figures are matplotlib SVGs with text as glyph paths: each glyph is defined once in the
figure's <defs> and placed by a <use> (20 426 placements in the 57 figures of the full report). WeasyPrint 70
draws a <use> by

- joining the reference "#DejaVuSans-31" to the image's URL, which for an image inlined in the HTML is its
  whole data: URL (up to 1 MB), and parsing that URL again, three times per glyph;
- parsing the glyph's path data again for every placement (a glyph has 20-60 Bézier curves);
- searching the figure's whole tree for the glyph's id at every level of the descent, once per glyph.

These are pure functions of their inputs, so each is computed once and reused here: a URL by its strings,
a path with an id by its data (and the sizes its units could refer to), an id's element by an index. A
few other pure helpers are memoized (transform lists, colours, style attributes) or written without their
per-call overhead (a plain number's size, the 3x3 matrix product, in the same order of operations). What
is written into the PDF does not change: the same operators with the same numbers, in the same order
(tests/test_report_fast_svg.py compares uncompressed PDFs byte for byte; benchmarks/pdf_render.py compares
the whole report's PDFs byte for byte and as page images).

`install()` patches WeasyPrint in this process (idempotent); `clear()` empties the caches.
"""

from __future__ import annotations

_INSTALLED = "_classical_dynamics_fast_svg"
# what the patches remember (dicts and lru_caches), emptied by clear() once a document is written: an
# inlined figure's URL is its whole data (up to 1 MB), which a long-lived process should not keep
_CACHES: list = []
CHECKED_ON = "70.0"  # the WeasyPrint these patches were compared against, byte for byte


def _memoized_path(path):
    """`weasyprint.svg.path.path`, replaying the operators and vertices of a path data string seen before.

    Only a path with an id is kept: one that <use> places (matplotlib's glyphs and markers); the rest are
    drawn once. A path's operators depend on its `d` string and, through units (em, %), on the font size
    and the image's inner size; they are appended to the stream without reading or changing its state
    (no colour, no matrix, no resource), so the appended items can be replayed as they are.
    """
    cache: dict[tuple, tuple[list, list]] = {}
    _CACHES.append(cache)

    def draw(svg, node, font_size):
        if node.get("id") is None:  # drawn once: a figure's line or patch, not a glyph or a marker
            path(svg, node, font_size)
            return
        key = (node.get("d", ""), font_size, svg.inner_width, svg.inner_height, svg.inner_diagonal)
        if (hit := cache.get(key)) is not None:
            operators, vertices = hit
            svg.stream.stream.extend(operators)
            node.vertices.extend(vertices)
            return
        start, vertices_before = len(svg.stream.stream), len(node.vertices)
        path(svg, node, font_size)
        operators = svg.stream.stream[start:]
        # only what a path appends can be replayed: no graphic state may have been pushed or popped
        if not any(isinstance(item, bytes) and item in (b"q", b"Q") for item in operators):
            cache[key] = (operators, list(node.vertices)[vertices_before:])

    return draw


def _indexed_get_child(get_child):
    """`Node.get_child` by an index of the tree's ids, built once per node it is asked of.

    WeasyPrint searches the whole subtree (ElementTree's find) at every level of its descent, for every
    glyph of every figure. The element found is the same: the first in document order with that id; the
    Node returned is reached through the same children (so cascaded as before). Where the Node tree does
    not follow the XML (text flattened by the cascade), WeasyPrint's own search answers.
    """

    def indexed(self, id_):
        index = self.__dict__.get("_fast_svg_ids")
        if index is None:
            first, parents = {}, {}
            for element in self._etree_node.iter():
                for child in element:
                    parents[child] = element
                if element is not self._etree_node:
                    first.setdefault(element.get("id"), element)
            index = self._fast_svg_ids = (first, parents)
        first, parents = index
        if (target := first.get(id_)) is None:
            return None
        chain = []
        while target is not self._etree_node:
            chain.append(target)
            target = parents[target]
        node = self
        for element in reversed(chain):
            node = next((child for child in node if child._etree_node is element), None)
            if node is None:
                return get_child(self, id_)
        return node

    return indexed


def _memoized(function, size: int | None = 1 << 16):
    import functools

    cached = functools.lru_cache(maxsize=size)(function)
    _CACHES.append(cached)
    return cached


def _fast_size(size):
    """`weasyprint.svg.utils.size` without a context manager per call: a plain number is returned at once."""

    def fast(string, font_size=None, percentage_reference=None):
        if not string:
            return 0
        try:
            return float(string)
        except ValueError:
            return size(string, font_size, percentage_reference)

    return fast


def _copying(function):
    """A memoized colour parser: the caller scales the colour's alpha in place, so each call gets a copy."""
    import copy

    cached = _memoized(function, 4096)
    return lambda string: copy.copy(cached(string))


def _copying_matrix(function):
    """A memoized transform parser: a Matrix is a list, so each caller gets its own copy."""
    cached = _memoized(function)

    def transform(*args):
        found = cached(*args)
        return type(found)(matrix=[row[:] for row in found])

    return transform


def _matmul(self, other):
    """`Matrix.__matmul__` in closed form: the same sums in the same order, so the same floats."""
    (b00, b01, b02), (b10, b11, b12), (b20, b21, b22) = other
    return type(self)(
        matrix=[
            [
                0 + a0 * b00 + a1 * b10 + a2 * b20,
                0 + a0 * b01 + a1 * b11 + a2 * b21,
                0 + a0 * b02 + a1 * b12 + a2 * b22,
            ]
            for a0, a1, a2 in self
        ]
    )


def clear() -> None:
    """Forget what the patches remember (the patches stay)."""
    for cache in _CACHES:
        (cache.cache_clear if hasattr(cache, "cache_clear") else cache.clear)()


def install() -> None:
    """Patch WeasyPrint's SVG drawing in this process, once; a WeasyPrint not checked is left alone."""
    import weasyprint
    import weasyprint.matrix as matrix
    import weasyprint.svg as svg
    import weasyprint.svg.defs as defs
    import weasyprint.svg.utils as utils

    if getattr(svg, _INSTALLED, False) or weasyprint.__version__ != CHECKED_ON:
        return
    # the parsed URL is a named tuple (immutable): shared safely
    parse_url = _memoized(utils.parse_url)
    for module in (svg, defs, utils):
        module.parse_url = parse_url
    import weasyprint.svg.css as svg_css

    svg_css.parse_url = parse_url

    get_href = svg.Node.get_href
    href_cache: dict[tuple, str | None] = {}
    _CACHES.append(href_cache)

    def cached_get_href(self, base_url):
        key = (self.get("{http://www.w3.org/1999/xlink}href"), self.get("href"), base_url)
        if key not in href_cache:
            href_cache[key] = get_href(self, base_url)
        return href_cache[key]

    svg.Node.get_href = cached_get_href
    svg.Node.get_child = _indexed_get_child(svg.Node.get_child)
    svg.TAGS["path"] = _memoized_path(svg.TAGS["path"])
    # a style attribute's declarations: read, never changed, by the cascade
    svg.parse_declarations = _memoized(svg.parse_declarations)
    svg.color = _copying(svg.color)
    svg.transform = defs.transform = _copying_matrix(utils.transform)
    import weasyprint.svg.text as text

    fast_size = _fast_size(utils.size)
    for module in (svg, defs, utils, text):
        module.size = fast_size
    matrix.Matrix.__matmul__ = _matmul
    setattr(svg, _INSTALLED, True)
