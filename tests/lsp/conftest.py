"""The language server `ncsight lsp` driven by a real client (pytest-lsp): the client starts
the built binary, speaks LSP on its standard input and output, and records what it publishes."""

import asyncio
import os
import pathlib
import sys
import time

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient

ROOT = pathlib.Path(__file__).resolve().parents[2]
NCSIGHT = os.environ.get("NCSIGHT_BIN") or next(
    (str(p) for p in (ROOT / "target/release/ncsight", ROOT / "target/debug/ncsight") if p.exists()),
    None,
)
if NCSIGHT is None:
    sys.exit("build ncsight first (cargo build --release -p ncsight-cli)")


@pytest_lsp.fixture(config=ClientServerConfig(server_command=[NCSIGHT, "lsp"]))
async def client(lsp_client: LanguageClient):
    # Every publication kept with its version (the client's own table keeps only the last).
    lsp_client.published = []

    features = lsp_client.protocol.fm.features
    kept = features[types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS]

    def on_diagnostics(params: types.PublishDiagnosticsParams):
        lsp_client.published.append((params.uri, params.version, params.diagnostics, time.monotonic()))
        return kept(params)

    features[types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS] = on_diagnostics

    await lsp_client.initialize_session(
        types.InitializeParams(capabilities=types.ClientCapabilities(), initialization_options={"machine": "gsk980tdi"})
    )
    yield
    await lsp_client.shutdown_session()


async def diagnostics(client, uri, version, timeout=30.0):
    """The diagnostics published for `uri` at `version` (waiting for them)."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        for u, v, d, _ in reversed(client.published):
            if u == uri and v == version:
                return list(d)
        await asyncio.sleep(0.01)
    raise AssertionError(f"no diagnostics for {uri} version {version} within {timeout} s: {client.published}")


def open_text(client, path, text, version=1):
    uri = path.as_uri()
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(uri=uri, language_id="gcode-ncsight", version=version, text=text))
    )
    return uri
