// The report's only script: the contents menu on small screens, a figure shown at print size on a phone's tap,
// a hint above a table wider than the screen, and the provenance panel that a number opens on click, tap or keyboard. Without it every number still links
// to its appendix row.
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("provenance-data").textContent);
  var panel = document.getElementById("provenance-panel");
  var opener = null;

  function el(tag, attrs, children) {
    var node = document.createElement(tag);
    Object.keys(attrs || {}).forEach(function (k) { node.setAttribute(k, attrs[k]); });
    (children || []).forEach(function (c) {
      node.appendChild(typeof c === "string" ? document.createTextNode(c) : c);
    });
    return node;
  }

  function item(term, value) {
    return [el("dt", {}, [term]), el("dd", {}, [value])];
  }

  function close() {
    if (panel.hidden) return;
    panel.hidden = true;
    if (opener) opener.setAttribute("aria-expanded", "false");
    if (opener) opener.focus();
    opener = null;
  }

  function open(link) {
    var scene = link.getAttribute("data-scene");
    var p = data[scene] || {};
    var unit = link.getAttribute("data-unit");
    var rows = [].concat(
      item("value", el("code", {}, [link.getAttribute("data-value") + (unit ? " " + unit : "")])),
      item("results file", el("code", {}, [p.file + " → numbers." + link.getAttribute("data-key")])),
      item("scene", el("a", {href: p.link}, [el("code", {}, [p.scene])])),
      item("commit", el("code", {}, [p.commit + (p.dirty ? " (uncommitted changes)" : "")])),
      item("scene SHA-256", el("code", {class: "hash"}, [p.input])),
      item("computed", p.finished.replace("T", " ")),
      item("rebuild", el("code", {}, [p.command]))
    );
    panel.textContent = "";
    panel.appendChild(el("p", {id: "provenance-title", class: "provenance-title"}, ["Where this number comes from"]));
    panel.appendChild(el("dl", {}, rows));
    panel.appendChild(el("p", {class: "provenance-links"}, [
      el("a", {href: "#prov-" + scene.replace("/", "-")}, ["its scene in the provenance appendix"])]));
    var button = el("button", {type: "button", class: "close", "aria-label": "Close"}, ["×"]);
    button.addEventListener("click", close);
    panel.appendChild(button);
    if (opener && opener !== link) opener.setAttribute("aria-expanded", "false");
    opener = link;
    link.setAttribute("aria-expanded", "true");
    panel.hidden = false;
    place(link);
    button.focus({preventScroll: true});
  }

  // Beside the number on a wide screen; a sheet along the bottom on a phone (see screen.css).
  function place(link) {
    panel.style.top = panel.style.left = "";
    if (window.matchMedia("(max-width: 700px)").matches) return;
    var r = link.getBoundingClientRect();
    var width = panel.offsetWidth;
    var left = Math.min(Math.max(8, r.left + window.scrollX), window.scrollX + document.documentElement.clientWidth - width - 8);
    panel.style.left = left + "px";
    panel.style.top = (r.bottom + window.scrollY + 6) + "px";
  }

  document.addEventListener("click", function (event) {
    // On a phone a tap on a figure shows it in place at its print size, scrolling sideways (its text as in
    // print); a second tap fits it again. Without the script the tap opens the figure's SVG.
    var figure = event.target.closest("a.full-size");
    if (figure && window.matchMedia("(max-width: 700px)").matches) {
      event.preventDefault();
      figure.setAttribute("aria-expanded", figure.classList.toggle("zoomed") ? "true" : "false");
      return;
    }
    var link = event.target.closest("a.num");
    if (link) {
      event.preventDefault();
      open(link);
    } else if (!panel.hidden && !panel.contains(event.target)) {
      close();
    }
  });
  document.addEventListener("keydown", function (event) {
    if (event.key === "Escape") { close(); document.body.classList.remove("menu-open"); }
    var link = event.target.closest && event.target.closest("a.num");
    if (link && event.key === " ") { event.preventDefault(); open(link); }   // a button opens on Space too
  });

  // A table wider than the screen says so above it (its side shadows alone were missed on a phone).
  function markWide() {
    document.querySelectorAll(".scroll").forEach(function (box) {
      box.classList.toggle("overflows", box.scrollWidth > box.clientWidth + 1);
    });
  }
  window.addEventListener("load", markWide);
  window.addEventListener("resize", markWide);

  var toggle = document.querySelector(".menu-toggle");
  toggle.addEventListener("click", function () {
    var opened = document.body.classList.toggle("menu-open");
    toggle.setAttribute("aria-expanded", opened ? "true" : "false");
    toggle.textContent = opened ? "Close" : "Contents";
  });
  document.getElementById("contents").addEventListener("click", function (event) {
    if (event.target.closest("a")) {
      document.body.classList.remove("menu-open");
      toggle.setAttribute("aria-expanded", "false");
      toggle.textContent = "Contents";
    }
  });
})();
