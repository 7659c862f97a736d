-- pandoc filter for the rendered user guide.
-- A link to another page of the guide (page.md or page.md#part) points at its HTML
-- (page.html#part), so the same Markdown links work on GitHub, in the program's Help browser and in
-- the installed HTML. A link that leaves docs/ (../README.md, a source file: any target starting
-- with ../) names a file of the source tree, which neither the program nor the package holds: it is
-- rendered as its text. Web addresses are left as they are (the Help browser hands them to the
-- desktop). The docs check test (tests/docs) follows the same rule: such links must resolve in the
-- repository.
function Link(el)
  local target = el.target
  if target:match("^%a[%w+.-]*:") then
    return el
  end
  if target:match("^%.%./") then
    return el.content
  end
  el.target = target:gsub("^([^#]-)%.md(#?)", "%1.html%2")
  return el
end

-- The page's title is its first top-level heading.
function Pandoc(doc)
  if not doc.meta.pagetitle and not doc.meta.title then
    for _, block in ipairs(doc.blocks) do
      if block.t == "Header" and block.level == 1 then
        doc.meta.pagetitle = pandoc.utils.stringify(block.content)
        break
      end
    end
  end
  return doc
end
