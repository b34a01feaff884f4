// Under Node there is no page to read the book's storage keys from (its <meta
// name="book-storage">, written by the build from physics_figures/topics.py storage_keys), so
// the tests name Dynamics's, as its pages do; require this before progress-store.js.
globalThis.BOOK_STORAGE = {
  book: "dynamics",
  progress: "dynamics-progress-v2",
  oldProgress: "dynamics-progress-v1",
  answers: "dynamics-questions:",
  review: "dynamics-review-v1",
  mock: "dynamics-mock-v1",
  exports: "dynamics-progress",
  cache: "dynamics-",
};
