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

-- Pictures (docs/images/*.png) are shown at most as wide as the help window's page (860 px; 420 px
-- in a table cell, where two stand side by side), so that the page needs no sideways scrolling. The
-- width comes from the PNG header; the viewer keeps the aspect ratio.
local function pngWidth(src)
  local dir = PANDOC_STATE.input_files[1]:match("^(.*)/[^/]*$") or "."
  local f = io.open(dir .. "/" .. src, "rb")
  if not f then
    return nil
  end
  local header = f:read(24)
  f:close()
  if not header or #header < 24 or header:sub(2, 4) ~= "PNG" then
    return nil
  end
  local b1, b2, b3, b4 = header:byte(17, 20)
  return ((b1 * 256 + b2) * 256 + b3) * 256 + b4
end

local function capWidth(img, cap)
  local width = tonumber(img.attributes.width) or pngWidth(img.src)
  if width and width > cap then
    img.attributes.width = tostring(cap)
  end
  return img
end

function Image(img)
  return capWidth(img, 860)
end

function Table(tbl)
  return pandoc.walk_block(tbl, { Image = function(img) return capWidth(img, 420) end })
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
