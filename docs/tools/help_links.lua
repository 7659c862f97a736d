-- pandoc filter for the rendered user guide.
-- A link to another page of the guide (page.md or page.md#part) points at its HTML
-- (page.html#part), so the same Markdown links work on GitHub, in the program's Help browser and in
-- the installed HTML. Links that leave docs/ (../README.md, source files) and web addresses are
-- left as they are: the Help browser hands them to the desktop.
function Link(el)
  local target = el.target
  if not target:match("^%a[%w+.-]*:") and not target:match("^%.%./") then
    el.target = target:gsub("^([^#]-)%.md(#?)", "%1.html%2")
  end
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
