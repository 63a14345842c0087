"""docs/flipcheck.md, "In your engine's tests", shows the two recipes as the examples that `make
test` runs: each file of examples/flipcheck-npm/ and examples/flipcheck-pytest/ must appear
there whole, as one fenced code block; so must the CI job's three of examples/flipcheck-ci/
("In a CI job"). Usage: check_doc_recipes.py SOURCE_DIR"""
import pathlib
import sys

FENCES = {".mjs": "js", ".json": "json", ".py": "python", ".sh": "sh"}


def main(source):
    doc = (source / "docs" / "flipcheck.md").read_text()
    files = sorted((source / "examples" / "flipcheck-npm").glob("*.*")) + \
        sorted((source / "examples" / "flipcheck-pytest").glob("*.py")) + \
        sorted((source / "examples" / "flipcheck-ci").glob("*.*"))
    stale = []
    for path in files:
        if path.suffix not in FENCES:
            continue
        block = f"```{FENCES[path.suffix]}\n{path.read_text()}```\n"
        if block not in doc:
            stale.append(str(path.relative_to(source)))
    if len(files) < 6:
        stale.append(f"expected the six example files, found {files}")
    if stale:
        print("docs/flipcheck.md does not show these examples as they are (copy each whole into "
              "its fenced block):\n  " + "\n  ".join(stale))
        return 1
    print(f"docs/flipcheck.md shows the {len(files)} example files as they are")
    return 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1])))
