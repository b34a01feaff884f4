/* The sidebar toggles a reader can see, made to work.

   A page has two ☰ buttons (.primary-toggle) and two "Contents" buttons
   (.secondary-toggle): pydata-sphinx-theme's, in its top bar, which
   sphinx-book-theme hides, and sphinx-book-theme's own, in the article header,
   which are the ones on screen. The themes' scripts bind only the first of each
   (document.querySelector), the hidden one, so the visible buttons did nothing
   (pydata-sphinx-theme #2451, sphinx-book-theme #988).

   A click on any other toggle is passed on to the bound one, so the themes' own
   code does the rest: below 992 px it opens the chapter list or the page's
   contents as a modal dialog (closed by Escape, a tap outside, or the dialog's
   Close button, book/_templates/menu-close.html); from 992 px ☰ folds the
   sidebar away and back. */
(() => {
  for (const kind of ["primary", "secondary"]) {
    const [bound, ...others] = document.querySelectorAll(`.${kind}-toggle`);
    for (const button of others) {
      button.addEventListener("click", (event) => {
        event.preventDefault();
        bound.click();
      });
    }
  }
})();
