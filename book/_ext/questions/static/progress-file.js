/* The file "Export progress" writes (progress.js, Your practice) and the class page reads
 * (class.js): the progress as the browser keeps it (format 2, progress-store.js, with the
 * schedule), plus the book's id and the checksum
 *
 *   {version: 2, book: "dynamics", student: "Amira Khan", sha256: "…64 hex digits…",
 *    attempts: [...], ...}
 *
 * student: the name the student gave when Export asked (kept in the store; absent when they
 * gave none); the file is named after it (exportFileName) and the class page names the
 * student by it.
 * book: the id of the book that wrote it (the build writes it into the page's data: the
 * keys of the book's topics, book/_ext/questions/store.py book_id), so a file from another
 * book is told apart. sha256: the checksum of the records, the lower-case hex SHA-256 of the
 * UTF-8 bytes of JSON.stringify(attempts), where attempts is the file's "attempts" array as
 * JSON.parse reads it back (so the file's spacing does not count; any change to a record
 * does). Anyone can compute it again: it catches a casual edit, not a determined student.
 *
 * ProgressStore.read reads these files, and the format 1 exports written before (with or
 * without these two fields; a format 1 file's checksum is of its attempts as written). A file
 * without the book's id or without a checksum is an export from before they existed: it is
 * read with every attempt and labelled "older export, not checked" (exportCheck); a file that
 * names another book, or whose records do not match their checksum, is refused.
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
   * Crypto the file has no sha256 (the class page reads it as an older export, not checked). */
  function exportFile(progress, book) {
    return recordsChecksum(progress.attempts).then(function (sha256) {
      var out = { version: progress.version, book: book };
      if (progress.student) out.student = progress.student;
      if (sha256) out.sha256 = sha256;
      Object.keys(progress).forEach(function (field) {
        if (!(field in out)) out[field] = progress[field];
      });
      return out;
    });
  }

  var OLDER = "older export, not checked";

  /* A promise of what an export (as JSON.parse read it) is, for the class page and Import:
   *   {ok: true, checked: true}   this book's, its records match their checksum;
   *   {ok: true, checked: false, label: "older export, not checked"}   no book id or no
   *     checksum: an export from before exports carried them (CLARIFICATIONS, Older exports),
   *     read with every attempt, but nothing tells whether it was edited;
   *   {ok: false, message}   another book's, or its records do not match their checksum (the
   *     message is the end of "NAME was refused: …"). */
  function exportCheck(progress, book) {
    var named = typeof progress.book === "string" && progress.book !== "";
    if (named && progress.book !== book) {
      return Promise.resolve({
        ok: false,
        message: 'it is from another book ("' + progress.book.slice(0, 40) + '"), not this one ("' + book + '").',
      });
    }
    if (!named || typeof progress.sha256 !== "string" || !progress.sha256) {
      return Promise.resolve({ ok: true, checked: false, label: OLDER });
    }
    return recordsChecksum(progress.attempts).then(function (sha256) {
      if (sha256 === null) {
        return {
          ok: false,
          message: "this browser cannot check its checksum here (open this page over https, or from the book's zip).",
        };
      }
      return sha256 === progress.sha256.toLowerCase()
        ? { ok: true, checked: true }
        : { ok: false, message: "its records do not match their checksum: it was changed after it was exported." };
    });
  }

  /* The name an export is saved under: "PREFIX-NAME-DATE.json" (PREFIX the book's KEYS.exports,
   * "dynamics-progress" in Dynamics), NAME the student's
   * name made safe for a file name on any system (letters and digits of any script kept, every
   * run of other characters one "-", at most 40 characters), DATE yyyy-mm-dd; without a name,
   * "PREFIX-DATE.json". */
  function exportFileName(student, date, prefix) {
    var safe = String(student || "")
      .normalize("NFC")
      .replace(/[^\p{L}\p{N}]+/gu, "-")
      .replace(/^-+|-+$/g, "")
      .slice(0, 40)
      .replace(/-+$/, "");
    return prefix + "-" + (safe ? safe + "-" : "") + date + ".json";
  }

  var api = {
    OLDER: OLDER,
    recordsChecksum: recordsChecksum,
    exportFile: exportFile,
    exportCheck: exportCheck,
    exportFileName: exportFileName,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.ProgressFile = api;
})(this);
