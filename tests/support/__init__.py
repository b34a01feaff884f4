"""Helpers the test modules share, each defined once here (tests/no_site/test_house.py checks that no
two test modules define one helper). What scripts/ shares with the tests lives in scripts/
(scripts/browser.py): no script imports a test.

- engine.py: the browser's scripts under Node (the marker, the mock draw, the sheet plan);
- pages.py: the built site's pages in Chromium (which page shows what, a page with its script
  errors watched, a question's form, what a page embeds or stores);
- pdf.py: a PDF as poppler-utils read it;
- sphinx.py: small Sphinx books built in a test's folder;
- templates.py: the bank's templates and answers as a student types them;
- weighing.py: a page's first-visit weight and layout shift."""
