// Every page's first script: errors and console.error calls from the first line on are kept
// in window.TRIBO_ERRORS, which each page shows in its #tribo-status (the browser tests read
// it). Not here: the status itself (page.js, sweep.js, branch.js).
window.TRIBO_ERRORS = [];
window.onerror = function (msg, src, line) { window.TRIBO_ERRORS.push(String(msg) + " (line " + line + ")"); };
(function () {
  var original = console.error;
  console.error = function () {
    window.TRIBO_ERRORS.push(Array.prototype.join.call(arguments, " "));
    original.apply(console, arguments);
  };
})();
