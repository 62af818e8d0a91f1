"""Execute one notebook (jupytext percent source) on the build's results; write .ipynb and HTML.

The notebook runs in notebooks/ with RESULTS_DIR pointing at the build's output folder
(relative, so no absolute path ends up in the outputs); cell ids are numbered, no timing
metadata is recorded and consecutive prints form one output (the kernel's flushes split them
depending on timing), so the same results give the same files.  Execution errors fail the job.
"""

import argparse
import os
import sys
from pathlib import Path

# nbformat validates with jsonschema, which imports the optional rfc3987-syntax when installed and that
# compiles 38 grammars on import (a second of CPU per notebook) for "iri" formats no notebook schema uses
sys.modules.setdefault("rfc3987_syntax", None)
# jupytext imports its Jupyter-server contents managers (and with them jupyter_server) when it can; only
# its reader is used here, and it stands without them (jupytext catches the ImportError)
for _manager in ("jupytext.sync_contentsmanager", "jupytext.async_contentsmanager"):
    sys.modules.setdefault(_manager, None)

import jupytext  # noqa: E402 (after the line above)
import nbclient  # noqa: E402
import nbformat  # noqa: E402
from nbconvert import HTMLExporter  # noqa: E402
from nbconvert.preprocessors import CoalesceStreamsPreprocessor  # noqa: E402

from torsional_contact.provenance import write_text  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--notebook", required=True, help="notebooks/NAME.py")
    p.add_argument("--results", required=True, help="the build's output folder, e.g. results")
    p.add_argument("--ipynb", required=True)
    p.add_argument("--html", required=True)
    p.add_argument("--timeout", type=int, required=True, help="seconds per cell")
    a = p.parse_args()
    source = Path(a.notebook)
    workdir = source.parent
    os.environ["RESULTS_DIR"] = os.path.relpath(a.results, workdir)
    os.environ["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"  # figures inline, not Agg
    notebook = jupytext.read(source)
    for index, cell in enumerate(notebook.cells):  # nbformat would draw random cell ids
        cell["id"] = f"cell-{index:03d}"
    client = nbclient.NotebookClient(notebook, kernel_name="python3", timeout=a.timeout, record_timing=False,
                                     resources={"metadata": {"path": str(workdir)}})
    client.execute()
    # one stream output per run of prints: how the kernel's flushes split them depends on timing
    notebook, _ = CoalesceStreamsPreprocessor().preprocess(notebook, {})
    for cell in notebook.cells:  # execution counts and ids are deterministic; drop the execution timestamps
        cell.get("metadata", {}).pop("execution", None)
    write_text(a.ipynb, nbformat.writes(notebook))
    html, _ = HTMLExporter(template_name="lab").from_notebook_node(notebook)
    write_text(a.html, html)
    print(f"executed {source} -> {a.ipynb}, {a.html}")


if __name__ == "__main__":
    main()
