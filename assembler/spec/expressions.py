"""A tiny arithmetic grammar for spec values that depend on the scene, e.g. ``-0.16 - table_length / 2``.

Specs come from strangers, so nothing here evaluates Python: expressions are parsed by this
recursive-descent parser into a closed set of operations (numbers, named variables, + - * /,
unary minus, parentheses) and evaluated against the variables the caller supplies.

    expression := term (("+" | "-") term)*
    term       := factor (("*" | "/") factor)*
    factor     := ("-" | "+") factor | NUMBER | NAME | "(" expression ")"
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass

OFFSET_VARIABLES: tuple[str, ...] = ("table_length", "table_width", "table_height")
"""Variables an offset expression may use: the arena's table size in metres."""

MAX_EXPRESSION_LENGTH = 200
"""Longer expressions are refused: an offset formula is a one-liner."""

_TOKEN = re.compile(r"\s*(?:(\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)|([A-Za-z_]\w*)|(.))")


class ExpressionError(ValueError):
    """The text is not a valid expression; the message says where and why."""


@dataclass(frozen=True)
class _Node:
    op: str  # "num", "var", "neg", "+", "-", "*", "/"
    value: float = 0.0
    name: str = ""
    left: _Node | None = None
    right: _Node | None = None


class _Parser:
    def __init__(self, text: str, allowed: tuple[str, ...]) -> None:
        self.text = text
        self.allowed = allowed
        self.tokens = self._tokenize(text)
        self.position = 0

    @staticmethod
    def _tokenize(text: str) -> list[tuple[str, str]]:
        tokens: list[tuple[str, str]] = []
        for number, name, other in _TOKEN.findall(text):
            if number:
                tokens.append(("num", number))
            elif name:
                tokens.append(("name", name))
            elif other.strip():
                if other not in "+-*/()":
                    raise ExpressionError(f"unexpected character {other!r} in expression {text!r}")
                tokens.append(("op", other))
        return tokens

    def _peek(self) -> tuple[str, str] | None:
        return self.tokens[self.position] if self.position < len(self.tokens) else None

    def _take(self) -> tuple[str, str]:
        token = self._peek()
        if token is None:
            raise ExpressionError(f"expression {self.text!r} ends too early")
        self.position += 1
        return token

    def parse(self) -> _Node:
        node = self._expression()
        if self._peek() is not None:
            raise ExpressionError(f"unexpected {self._peek()[1]!r} in expression {self.text!r}")  # type: ignore[index]
        return node

    def _expression(self) -> _Node:
        node = self._term()
        while (token := self._peek()) and token[1] in ("+", "-"):
            self._take()
            node = _Node(token[1], left=node, right=self._term())
        return node

    def _term(self) -> _Node:
        node = self._factor()
        while (token := self._peek()) and token[1] in ("*", "/"):
            self._take()
            node = _Node(token[1], left=node, right=self._factor())
        return node

    def _factor(self) -> _Node:
        kind, text = self._take()
        if kind == "op" and text in ("-", "+"):
            inner = self._factor()
            return _Node("neg", left=inner) if text == "-" else inner
        if kind == "num":
            return _Node("num", value=float(text))
        if kind == "name":
            if text not in self.allowed:
                raise ExpressionError(
                    f"unknown variable {text!r} in expression {self.text!r}; "
                    f"allowed: {', '.join(self.allowed)}"
                )
            return _Node("var", name=text)
        if text == "(":
            node = self._expression()
            if self._take()[1] != ")":
                raise ExpressionError(f"missing ')' in expression {self.text!r}")
            return node
        raise ExpressionError(f"unexpected {text!r} in expression {self.text!r}")


def parse_expression(text: str, allowed: tuple[str, ...] = OFFSET_VARIABLES) -> _Node:
    """Parse ``text``, raising :class:`ExpressionError` on anything outside the grammar."""
    if len(text) > MAX_EXPRESSION_LENGTH:
        raise ExpressionError(f"expression longer than {MAX_EXPRESSION_LENGTH} characters")
    if not text.strip():
        raise ExpressionError("empty expression")
    return _Parser(text, allowed).parse()


def _evaluate(node: _Node, variables: Mapping[str, float]) -> float:
    if node.op == "num":
        return node.value
    if node.op == "var":
        if node.name not in variables:
            raise ExpressionError(f"variable {node.name!r} needs a value (pass {node.name}=...)")
        return float(variables[node.name])
    if node.op == "neg":
        return -_evaluate(node.left, variables)  # type: ignore[arg-type]
    left = _evaluate(node.left, variables)  # type: ignore[arg-type]
    right = _evaluate(node.right, variables)  # type: ignore[arg-type]
    if node.op == "+":
        return left + right
    if node.op == "-":
        return left - right
    if node.op == "*":
        return left * right
    if right == 0.0:
        raise ExpressionError("division by zero")
    return left / right


def evaluate_expression(value: float | str, variables: Mapping[str, float]) -> float:
    """The value of a number or expression text, with ``variables`` bound; always finite."""
    if isinstance(value, (int, float)):
        return float(value)
    result = _evaluate(parse_expression(value), variables)
    if not math.isfinite(result):
        raise ExpressionError(f"expression {value!r} is not finite with {dict(variables)}")
    return result
