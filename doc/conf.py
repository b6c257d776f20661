# Sphinx configuration of the impact manual (MyST Markdown; the reduced library's API through
# Doxygen XML and Breathe). Built by `cmake --build build --target doc`, which passes the
# Doxygen XML folder in IMPACT_DOXYGEN_XML; the test doc.build runs it with -W --keep-going.
import os

project = "impact"
author = "the impact authors"
copyright = "the impact authors"
version = release = "0.1.0"

extensions = ["myst_parser", "breathe"]
source_suffix = {".md": "markdown"}
master_doc = "index"
exclude_patterns = ["_build", "tools"]

# Headings become link targets (#anchor) down to level 3.
myst_heading_anchors = 3
# Most code blocks are shell commands or parameter files; no lexer is guessed for the rest.
highlight_language = "none"
# Typographic quotes, but no dashes: "--velocities" in a help text is an option, not an en dash.
smartquotes_action = "qe"

breathe_projects = {"impact_reduced": os.environ.get("IMPACT_DOXYGEN_XML", "_doxygen/xml")}
breathe_default_project = "impact_reduced"
breathe_domain_by_extension = {"hpp": "cpp", "h": "cpp"}
breathe_show_include = True

html_theme = "sphinx_rtd_theme"
html_title = "impact manual"
html_theme_options = {"navigation_depth": 3, "collapse_navigation": False}
html_static_path = ["_static"]
html_css_files = ["manual.css"]
# A build that is the same from one run to the next (no date in the footer).
html_last_updated_fmt = None
html_show_sourcelink = False


# One page per header (doc/api/) renders each header with Breathe's doxygenfile, which declares
# the header's namespaces (impact, impact::reduced) again on every page; Sphinx reports each
# repetition as a duplicate C++ declaration. Those two namespace declarations, and only they,
# are expected; every other warning stays an error under -W.
import logging

_namespaces = ("impact", "reduced", "impact::reduced")


class _RepeatedNamespace(logging.Filter):
    def filter(self, record):
        message = record.getMessage()
        if not message.startswith("Duplicate C++ declaration"):
            return True
        return not any(message.endswith(f"Declaration is '.. cpp:type:: {name}'.")
                       for name in _namespaces)


def setup(app):
    logging.getLogger("sphinx.sphinx.domains.cpp").addFilter(_RepeatedNamespace())
