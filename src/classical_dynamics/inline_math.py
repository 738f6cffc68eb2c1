"""Inline math, $...$, as HTML: italic variables, Greek, real sub- and superscripts, upright labels.

One syntax everywhere: templates, captions written by the studies, table headers, and (through
matplotlib's mathtext) figure labels, so a symbol reads the same in text and figure. The syntax is
the TeX subset a physicist types without thinking:

    $\\nu_\\mathrm{c}$   $m_1$   $q_1^2$   $e^{2\\mu_1\\varphi_2}$   $(1 - e^2)^{-3/2}$
    $\\dot\\psi$   $\\sqrt{bc}$

Latin and lower-case Greek letters are italic, digits and upper-case Greek upright, \\mathrm{} and
\\text{} upright (a label such as the c of "critical"), function names (\\sin, \\ln) upright. Source
spacing is kept as typed, '-' becomes a real minus. An unknown command is an error: the build stops
rather than show a reader raw markup. HTML and WeasyPrint render the result identically.
"""

from __future__ import annotations

import html
import re

GREEK = {
    "alpha": "α",
    "beta": "β",
    "gamma": "γ",
    "delta": "δ",
    "epsilon": "ϵ",
    "varepsilon": "ε",
    "zeta": "ζ",
    "eta": "η",
    "theta": "θ",
    "vartheta": "ϑ",
    "iota": "ι",
    "kappa": "κ",
    "lambda": "λ",
    "mu": "μ",
    "nu": "ν",
    "xi": "ξ",
    "pi": "π",
    "rho": "ρ",
    "sigma": "σ",
    "tau": "τ",
    "upsilon": "υ",
    "phi": "φ",
    "varphi": "φ",
    "chi": "χ",
    "psi": "ψ",
    "omega": "ω",
    "Gamma": "Γ",
    "Delta": "Δ",
    "Theta": "Θ",
    "Lambda": "Λ",
    "Xi": "Ξ",
    "Pi": "Π",
    "Sigma": "Σ",
    "Phi": "Φ",
    "Psi": "Ψ",
    "Omega": "Ω",
}
SYMBOLS = {
    "times": "×",
    "cdot": "·",
    "pm": "±",
    "mp": "∓",
    "le": "≤",
    "leq": "≤",
    "ge": "≥",
    "geq": "≥",
    "ne": "≠",
    "neq": "≠",
    "approx": "≈",
    "sim": "∼",
    "simeq": "≃",
    "propto": "∝",
    "to": "→",
    "rightarrow": "→",
    "leftarrow": "←",
    "ll": "≪",
    "gg": "≫",
    "equiv": "≡",
    "infty": "∞",
    "partial": "∂",
    "nabla": "∇",
    "ldots": "…",
    "dots": "…",
    "cdots": "⋯",
    "circ": "°",
    "prime": "′",
    "langle": "⟨",
    "rangle": "⟩",
    "{": "{",
    "}": "}",
    "|": "‖",
    "%": "%",
    "sum": "∑",
    "int": "∫",
    "odot": "☉",
    "star": "⋆",
    "ast": "∗",
    "in": "∈",
    "mid": "|",
    "lvert": "|",
    "rvert": "|",
    "lfloor": "⌊",
    "rfloor": "⌋",
    "ell": "ℓ",
    "hbar": "ħ",
    "oplus": "⊕",
    "perp": "⊥",
    "parallel": "∥",
    "angle": "∠",
    "degree": "°",
    "div": "÷",
}
SPACES = {",": "\u2009", ";": " ", ":": " ", " ": " ", "quad": "\u2003", "qquad": "\u2003\u2003", "!": ""}
FUNCTIONS = {
    "sin",
    "cos",
    "tan",
    "cot",
    "sec",
    "csc",
    "sinh",
    "cosh",
    "tanh",
    "coth",
    "arcsin",
    "arccos",
    "arctan",
    "ln",
    "log",
    "exp",
    "max",
    "min",
    "det",
    "sgn",
    "mod",
    "Re",
    "Im",
    "arg",
    "si",
    "ci",
    "sn",
    "cn",
    "dn",
    "am",
    "erf",
    "tr",
}
ACCENTS = {
    "dot": "\u0307",
    "ddot": "\u0308",
    "hat": "\u0302",
    "bar": "\u0304",
    "tilde": "\u0303",
    "vec": "\u20d7",
    "breve": "\u0306",
}
UPRIGHT = {"mathrm", "text", "textrm", "operatorname", "mathup", "rm", "mathsf"}
BOLD = {"mathbf", "boldsymbol", "bm"}
FRACTIONS = {("1", "2"): "½", ("1", "3"): "⅓", ("2", "3"): "⅔", ("1", "4"): "¼", ("3", "4"): "¾"}
IGNORED = {"left", "right", "big", "Big", "bigl", "bigr", "Bigl", "Bigr", "displaystyle", "textstyle"}

_TOKEN = re.compile(r"\\([A-Za-z]+|.)|(\s+)|(.)", re.S)
_GLUE = re.compile(r"(</span>) (=|&lt;|&gt;|≤|≥|≈) ")  # "ν = 0.5" never breaks at the "="
_INLINE = re.compile(r"(?<!\\)\$(.+?)(?<!\\)\$", re.S)


class MathError(ValueError):
    pass


class _Parser:
    def __init__(self, source: str):
        self.source = source
        self.tokens = [(m.group(1), m.group(2), m.group(3)) for m in _TOKEN.finditer(source)]
        self.i = 0

    def error(self, what: str):
        raise MathError(f"inline math ${self.source}$: {what}")

    def peek(self):
        return self.tokens[self.i] if self.i < len(self.tokens) else None

    def next(self):
        token = self.peek()
        if token is None:
            self.error("ends early")
        self.i += 1
        return token

    def argument(self, mode: str) -> str:
        """One argument: a {group} or a single token."""
        while (tok := self.peek()) is not None and tok[1]:
            self.i += 1  # TeX skips spaces before an argument
        command, space, char = self.next()
        if char == "{":
            return self.sequence(mode, until="}")
        self.i -= 1
        return self.atom(mode)

    def raw_group(self) -> str:
        """The text of a {group} taken literally (for \\text{...})."""
        while (tok := self.peek()) is not None and tok[1]:
            self.i += 1  # TeX skips spaces before an argument, as argument() does
        command, space, char = self.next()
        if char != "{":
            return html.escape(char or space or "")
        depth, out = 1, []
        while True:
            command, space, char = self.next()
            if char == "{":
                depth += 1
            elif char == "}":
                depth -= 1
                if depth == 0:
                    return html.escape("".join(out))
            out.append(("\\" + command) if command else (space or char))

    def sequence(self, mode: str, until: str | None = None) -> str:
        out = []
        while True:
            token = self.peek()
            if token is None:
                if until:
                    self.error(f"missing '{until}'")
                return "".join(out)
            if until is not None and token[2] == until:
                self.i += 1
                return "".join(out)
            if token[2] == "}":
                self.error("unbalanced '}'")
            out.append(self.scripted(mode))

    def scripted(self, mode: str) -> str:
        base = self.atom(mode)
        sub = sup = ""
        while (tok := self.peek()) is not None and tok[2] in ("_", "^"):
            self.i += 1
            if tok[2] == "_":
                sub = self.argument(mode)
            else:
                sup = self.argument(mode)
        if sub:
            base += f"<sub>{sub}</sub>"
        if sup:
            base += f"<sup>{sup}</sup>"
        return base

    def letter(self, char: str, mode: str) -> str:
        if mode == "upright":
            return html.escape(char)
        if ("a" <= char.lower() <= "z") or ("α" <= char <= "ω") or char in "ϵϑφϕℓ":
            return f"<i>{char}</i>"
        return html.escape(char)

    def atom(self, mode: str) -> str:
        command, space, char = self.next()
        if space:
            return " "
        if char is not None:
            if char == "{":
                return self.sequence(mode, until="}")
            if char == "-":
                return "\u2212"
            if char == "'":
                return "′"
            if char == "*":
                return "*"
            if char in "_^":
                self.error(f"'{char}' with nothing before it")
            return self.letter(char, mode)
        if command in GREEK:
            greek = GREEK[command]
            return self.letter(greek, mode) if greek.islower() else greek
        if command in SYMBOLS:
            return html.escape(SYMBOLS[command])
        if command in SPACES:
            return SPACES[command]
        if command in FUNCTIONS:
            while (following := self.peek()) is not None and following[1]:
                self.i += 1  # the source's space becomes the thin one
            spaced = following is not None and not (following[2] and following[2] in ",.;:)]}(_^")
            return f"<span class=fn>{command}</span>" + ("\u2009" if spaced else "")
        if command in IGNORED:
            return ""
        if command in UPRIGHT:
            if command in ("text", "textrm"):
                return self.raw_group()
            if command == "operatorname":  # a function's name, spaced from its argument as \sin is
                name = self.argument("upright")
                while (following := self.peek()) is not None and following[1]:
                    self.i += 1
                spaced = following is not None and not (following[2] and following[2] in ",.;:)]}(_^")
                return f"<span class=fn>{name}</span>" + ("\u2009" if spaced else "")
            return self.argument("upright")
        if command in BOLD:
            return f"<b>{self.argument(mode)}</b>"
        if command in ACCENTS:
            inner = self.argument(mode)
            mark = ACCENTS[command]
            # the mark right after the first letter, inside its tags: in another text run the
            # shaper cannot attach it and prints a dotted circle
            return re.sub(r"^((?:<[^>]+>)*)([^<])", lambda m: m.group(1) + m.group(2) + mark, inner, count=1)
        if command == "sqrt":
            inner = self.argument(mode)
            return f"√<span class=radicand>{inner}</span>"
        if command in ("frac", "tfrac", "dfrac"):
            num_source = self._peek_group()
            numerator = self.argument(mode)
            den_source = self._peek_group()
            denominator = self.argument(mode)
            if (num_source, den_source) in FRACTIONS:
                return FRACTIONS[(num_source, den_source)]
            wrap = lambda s: f"({s})" if re.search(r"[ +\u2212]", re.sub(r"<[^>]+>", "", s)) else s
            return f"{wrap(numerator)}/{wrap(denominator)}"
        self.error(f"unknown command \\{command}")

    def _peek_group(self) -> str | None:
        """The literal text of the next argument if it is plain (for ½ from \\frac12)."""
        j = self.i
        while j < len(self.tokens) and self.tokens[j][1]:
            j += 1
        if j >= len(self.tokens):
            return None
        command, space, char = self.tokens[j]
        if char == "{":
            text = []
            for command, space, char in self.tokens[j + 1 :]:
                if char == "}":
                    return "".join(text)
                if command or space:
                    return None
                text.append(char)
            return None
        return char


def math_html(source: str) -> str:
    """One $...$ body as HTML. Attributes go unquoted, so the HTML can stand inside a quoted string
    of a template (a caption in a Jinja list) without ending it."""
    parser = _Parser(source.strip())
    body = parser.sequence("math")
    # a short formula never breaks across lines; a long one may, at its spaces
    kind = "math" if len(re.sub(r"<[^>]+>", "", body)) <= 24 else "math-long"
    return f"<span class={kind}>{body}</span>"


def render_text(text: str) -> str:
    """Plain text with $...$ as HTML: the text escaped, the math converted, straight double quotes turned
    (“…”), and a reference (Ex. XI.1, Art. 29) kept on one line."""
    out, last = [], 0
    for match in _INLINE.finditer(text):
        out.append(_prose(text[last : match.start()], text[last - 1 : last]))
        out.append(math_html(match.group(1)))
        last = match.end()
    out.append(_prose(text[last:], text[last - 1 : last]))
    return _GLUE.sub("\\1\u00a0\\2\u00a0", "".join(out)).replace("\\$", "$")


_REFERENCE = re.compile(r"\b((?:Exs?|Arts?|eqs?|Fig|Figs)\.) ([IVXL]+\.\d+|\d+)")


def _prose(text: str, before: str) -> str:
    """Text between formulas: escaped; a quote opens after a space, a bracket or the start, else closes."""
    chars = []
    for i, char in enumerate(text):
        if char == '"':
            previous = text[i - 1] if i else before
            char = "\u201c" if previous in ("", " ", "(", "[", "\n", "\u00a0") else "\u201d"
        chars.append(char)
    escaped = html.escape("".join(chars), quote=False)
    return _REFERENCE.sub("<span class=nw>\\1\u00a0\\2</span>", escaped)


def render_markup(markup: str) -> str:
    """HTML (a template's source) with $...$ converted; the HTML around it is left as it is."""
    return _INLINE.sub(lambda m: math_html(m.group(1)), markup)


_SCRIPTS = {
    "sub": str.maketrans("0123456789+−=()aeoxhklmnpst", "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₒₓₕₖₗₘₙₚₛₜ"),
    "sup": str.maketrans("0123456789+−=()in", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁱⁿ"),
}
_SCRIPT_CHARS = {kind: {chr(code) for code in table.values()} for kind, table in _SCRIPTS.items()}


def _script(match: re.Match) -> str:
    """A sub- or superscript as its Unicode characters (ω₃², not ω32), or _x / ^(x y) where one has none."""
    kind, body = match.group(1), html.unescape(re.sub(r"<[^>]+>", "", match.group(2)))
    scripted = body.translate(_SCRIPTS[kind])
    if set(scripted) <= _SCRIPT_CHARS[kind]:
        return scripted
    return ("_" if kind == "sub" else "^") + (body if len(body) == 1 else f"({body})")


def _radicand(match: re.Match) -> str:
    body = html.unescape(re.sub(r"<[^>]+>", "", match.group(1)))
    return body if len(body) == 1 else f"({body})"  # √(g/a), not √g/a


def plain_text(text: str) -> str:
    """$...$ as readable plain text (alt attributes, PDF bookmarks, CSV): tags dropped, math kept, scripts
    as Unicode scripts where they exist."""
    text = re.sub(r"<(sub|sup)>((?:(?!</?\1>).)*)</\1>", _script, render_text(text))
    text = re.sub(r"<span class=radicand>((?:(?!</?span).)*)</span>", _radicand, text)
    return html.unescape(re.sub(r"<[^>]+>", "", text))
