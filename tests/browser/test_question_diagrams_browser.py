"""New numbers relabels a question's diagram (issue 37), in Chromium: after it, the diagram is
the new variant's own SVG, loaded, and its alt text carries that variant's numbers."""

from __future__ import annotations

import pytest
from browser import question_pages, serve_site
from support.pages import page_without_errors
from support.templates import diagram_numbers

from physics_figures import bank

pytestmark = [pytest.mark.site, pytest.mark.browser]


@pytest.mark.parametrize("key", ["puck-components", "collision-third-law"])
def test_new_numbers_show_the_new_variant_s_diagram(site_dir, key, browser):
    pages = question_pages(site_dir)
    with serve_site(site_dir) as base_url, \
            page_without_errors(browser, base_url + pages[key]) as page:
        section = page.locator(f"#question-{key}")
        image = section.locator("img.q-diagram")
        assert all(number in image.get_attribute("alt") for number in diagram_numbers(bank.TEMPLATES[key].variant(0)))
        form = page.locator(f'form.q-form[data-question="{key}"]')
        form.locator("button.q-new").click()
        page.wait_for_function(
            f"document.querySelector('form.q-form[data-question=\"{key}\"]').dataset.variant !== '0'")
        index = int(form.get_attribute("data-variant"))
        assert image.get_attribute("src").endswith(f"/_static/questions/{key}-diagram-{index}.svg")
        page.wait_for_function(f"document.querySelector('#question-{key} img.q-diagram').complete")
        assert image.evaluate("img => img.naturalWidth") > 0, "the new diagram did not load"
        alt = image.get_attribute("alt")
        for number in diagram_numbers(bank.TEMPLATES[key].variant(index)):
            assert number in alt, (index, number, alt)
