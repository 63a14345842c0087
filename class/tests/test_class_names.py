"""Students' names in every script (docs/class.md, "Names"): limits.person_name accepts a name as
people spell it in Latin, Cyrillic, Greek, Arabic, Persian (with its zero-width non-joiner),
Hebrew, Devanagari, Tamil, Bengali, Thai, CJK, Hangul and emoji (with their joiners, variation
selectors and a flag's tags), and refuses control characters, the marks and overrides of
direction, path separators and a name of nothing visible, each in one line naming the field;
pooled.file_stem keeps every letter, mark and symbol of such a name, and `bookspin fit` (the
command and the module the server fits with) names a recording of that file name by the very
stem, so the projector's rows and the fit's table name a student's toss alike."""
import json
import shutil
import unicodedata

import pytest

from class_server import REAL, real_csv
from conftest import SOURCE_DIR, read_csv, run_cli

import sys
sys.path.insert(0, str(SOURCE_DIR / "class"))
from bookspin_class import limits, pooled  # noqa: E402

# A name per script a classroom may bring, as typed (NFC unless said).
NAMES = {
    "Latin": "Zoë Ångström",
    "Latin, typed decomposed": unicodedata.normalize("NFD", "Zoë Ångström"),
    "Cyrillic": "Юлия Ковалёва",
    "Greek": "Αθηνά Παππά",
    "Arabic": "فاطمة الزهراء",
    "Persian (ZWNJ)": "مهر\u200cانگیز",
    "Hebrew": "נועה כהן",
    "Devanagari": "प्रिया शर्मा",
    "Tamil": "தமிழ்செல்வி",
    "Bengali": "অর্পিতা",
    "Thai": "สมชาย ใจดี",
    "Chinese": "王芳",
    "Japanese": "山田太郎",
    "Hangul": "김지민",
    "emoji (ZWJ, skin tone)": "Sam 👩🏽\u200d🔬",
    "emoji (variation selector)": "❤\ufe0f Lea",
    "emoji flag (tags)": "🏴\U000e0067\U000e0062\U000e0073\U000e0063\U000e0074\U000e007f Iain",
}


@pytest.mark.parametrize("script", NAMES)
def test_a_name_in_every_script_is_accepted_in_nfc(script):
    typed = NAMES[script]
    assert limits.person_name({"name": f"  {typed} "}) == unicodedata.normalize("NFC", typed)


@pytest.mark.parametrize("name, reason", [
    ("", '"name": empty'),
    ("   ", '"name": empty'),
    ("anna\x07", '"name": character U+0007 is not allowed in a name'),
    ("anna\u0085b", '"name": character U+0085 is not allowed in a name'),
    ("\u202eanna", '"name": character U+202E is not allowed in a name'),
    ("anna\u2066b\u2069", '"name": character U+2066 is not allowed in a name'),
    ("anna\u200fb", '"name": character U+200F is not allowed in a name'),
    ("an\u00adna", '"name": character U+00AD is not allowed in a name'),
    ("anna\ufeff", '"name": character U+FEFF is not allowed in a name'),
    ("anna\U000e0067", '"name": character U+E0067 is not allowed in a name'),
    ("a/b", '"name": character U+002F is not allowed in a name'),
    ("a\\b", '"name": character U+005C is not allowed in a name'),
    ("anna\ue000", '"name": character U+E000 is not allowed in a name'),
    ("\u200c\u200d", '"name": no letter, digit or symbol'),
    ("x" * 81, '"name": 81 characters, over the limit of 80'),
])
def test_a_name_that_hides_or_reorders_itself_is_refused_in_one_line(name, reason):
    with pytest.raises(Exception) as refused:
        limits.person_name({"name": name})
    assert refused.value.status == 400
    assert json.loads(refused.value.text) == {"error": reason}


@pytest.mark.parametrize("name, stem", [
    ("प्रिया शर्मा", "प्रिया-शर्मा-4"),        # every vowel sign and virama kept
    ("மு.க. தமிழ்செல்வி", "மு.க.-தமிழ்செல்வி-4"),
    ("مهر\u200cانگیز", "مهر\u200cانگیز-4"),  # the ZWNJ of Persian spelling kept
    ("Sam 👩🏽\u200d🔬", "Sam-👩🏽\u200d🔬-4"),
    (unicodedata.normalize("NFD", "Zoë"), "Zoë-4"),
    ("O'Brien", "O'Brien-4"),
    ("anna  -  b", "anna-b-4"),
    ("a/b:c*d?e\"f<g>h|i\\j", "a-b-c-d-e-f-g-h-i-j-4"),
    ("-x", "x-4"),
    (".hidden", "hidden-4"),
    ("???", "toss-4"),
])
def test_a_file_stem_keeps_every_letter_mark_and_symbol(name, stem):
    assert pooled.file_stem(name, 4) == stem


def test_a_long_name_is_cut_before_a_whole_character_within_the_fits_limit():
    for name in ("山田太郎" * 20, "👩🏽\u200d🔬" * 20, "प्रिया" * 13):
        stem = pooled.file_stem(name, 123)
        assert len(stem.encode("utf-8")) <= pooled.MAX_FILE_NAME_BYTES, stem
        cut = stem[:-len("-123")]
        assert name.startswith(cut) and cut
        rest = name[len(cut):]  # the cut falls where no mark or joiner ties on
        assert unicodedata.category(rest[0])[0] != "M" and rest[0] not in "\u200c\u200d"
        assert not cut.endswith("\u200d")


def test_bookspin_fit_names_each_recording_by_its_file_stem(tmp_path, bookspin):
    """The class set's file names, as the server writes them, are the names `bookspin fit`
    gives the recordings in its table: the command line's -fit.csv and the module's rows."""
    if not REAL.is_dir():
        pytest.skip(f"no real recordings at {REAL}")
    names = ["प्रिया शर्मा", "مهر\u200cانگیز", "Sam 👩🏽\u200d🔬", "สมชาย ใจดี", "김지민",
             "山田太郎" * 20]
    recordings = ["12-10-56", "12-13-01", "12-13-51", "12-22-44", "12-29-59", "12-38-00"]
    files = {pooled.file_stem(name, seq): real_csv(recording)
             for seq, (name, recording) in enumerate(zip(names, recordings), start=1)}
    paths = pooled.write_set(tmp_path, files)
    fit = bookspin.fit(paths)
    assert {row["recording"] for row in fit.tosses} == set(files)
    out = tmp_path / "out"
    run_cli("fit", *paths, "-o", out)
    tables = list(out.glob("*-fit.csv"))
    assert len(tables) == 1, sorted(p.name for p in out.iterdir())
    assert set(read_csv(tables[0])["recording"]) == set(files)
    shutil.rmtree(out)
