/* The file "Export progress" writes (progress.js, Your practice) and the class page reads
 * (class.js): the progress as the browser keeps it (format 2, progress-store.js, with the
 * schedule), plus two fields
 *
 *   {version: 2, book: "dynamics", sha256: "…64 hex digits…", attempts: [...], ...}
 *
 * book: the id of the book that wrote it (the build writes it into the page's data: the
 * keys of the book's topics, book/_ext/questions/store.py book_id), so a file from another
 * book is told apart. sha256: the checksum of the records, the lower-case hex SHA-256 of the
 * UTF-8 bytes of JSON.stringify(attempts), where attempts is the file's "attempts" array as
 * JSON.parse reads it back (so the file's spacing does not count; any change to a record
 * does). Anyone can compute it again: it catches a casual edit, not a determined student.
 *
 * ProgressStore.read reads these files, and the format 1 exports written before (with or
 * without these two fields; a format 1 file's checksum is of its attempts as written).
 * Plain JavaScript; Web Crypto (crypto.subtle: https, http://localhost and file:// pages).
 * Runs under Node for the tests. */
(function (root) {
  "use strict";

  function subtleCrypto() {
    var found = typeof crypto !== "undefined" ? crypto : root.crypto;
    return (found && found.subtle) || null;
  }

  /* A promise of the records' checksum (above), or of null where the browser offers no Web
   * Crypto (a page served over plain http from another computer). */
  function recordsChecksum(attempts) {
    var subtle = subtleCrypto();
    if (!subtle) return Promise.resolve(null);
    var bytes = new TextEncoder().encode(JSON.stringify(attempts));
    return subtle.digest("SHA-256", bytes).then(function (digest) {
      return Array.prototype.map
        .call(new Uint8Array(digest), function (byte) {
          return (byte < 16 ? "0" : "") + byte.toString(16);
        })
        .join("");
    });
  }

  /* A promise of the file to write for `progress` (as kept: every field stays) from `book`:
   * version, book and sha256 first, so a reader opening the file sees them. Without Web
   * Crypto the file has no sha256 (and the class page will refuse it, saying why). */
  function exportFile(progress, book) {
    return recordsChecksum(progress.attempts).then(function (sha256) {
      var out = { version: progress.version, book: book };
      if (sha256) out.sha256 = sha256;
      Object.keys(progress).forEach(function (field) {
        if (!(field in out)) out[field] = progress[field];
      });
      return out;
    });
  }

  /* A promise of null when an export (as readProgress read it) is this book's and its records
   * match their checksum; else of what is wrong, as the end of "NAME was refused: …". */
  function exportProblem(progress, book) {
    var problem = null;
    if (typeof progress.book !== "string" || !progress.book) {
      problem =
        "it does not say which book it is from (an export of this book's Your practice does; " +
        "an older one does not: export it again).";
    } else if (progress.book !== book) {
      problem = 'it is from another book ("' + progress.book.slice(0, 40) + '"), not this one ("' + book + '").';
    } else if (typeof progress.sha256 !== "string" || !progress.sha256) {
      problem = "it has no checksum of its records (export it again from Your practice).";
    }
    if (problem) return Promise.resolve(problem);
    return recordsChecksum(progress.attempts).then(function (sha256) {
      if (sha256 === null) {
        return "this browser cannot check its checksum here (open this page over https, or from the book's zip).";
      }
      return sha256 === progress.sha256.toLowerCase()
        ? null
        : "its records do not match their checksum: it was changed after it was exported.";
    });
  }

  var api = { recordsChecksum: recordsChecksum, exportFile: exportFile, exportProblem: exportProblem };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.ProgressFile = api;
})(this);
