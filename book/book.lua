-- Pandoc filter for the course book, used in two passes (see book/build.sh).
--
-- First pass, one note at a time (output format markdown), with metadata
--   source:     the note's path from the repository root, e.g. chapters/04_integral_matching/README.md
--   book_files: every note that is in the book
--   retitle:    optional new text for the note's first heading
-- it makes the note's paths and anchors mean the same thing once all notes are one document:
--   * image paths, written relative to the note, become relative to the repository root;
--     an image whose file does not exist becomes a line of text naming it;
--   * every heading id gets the note's key as prefix, and the note's first heading is the
--     key itself, so "chapters/04_integral_matching/README.md#hard-cases" becomes the in-book
--     anchor "#chapters-04_integral_matching--hard-cases" (an EVIDENCE.md's key ends in "-evidence");
--   * a link to a file that is not in the book (source code; the evidence pages in the lessons'
--     edition) keeps its text only.
--
-- Second pass, on the whole book (output format latex): a figure also written as PDF is
-- included as the PDF (vector), otherwise as the PNG.

local function file_exists(path)
  local f = io.open(path, "r")
  if f then
    f:close()
    return true
  end
  return false
end

-- "chapters/05_x/../../figures/a.png" -> "figures/a.png"
local function normalize(path)
  local parts = {}
  for part in path:gmatch("[^/]+") do
    if part == ".." then
      table.remove(parts)
    elseif part ~= "." then
      table.insert(parts, part)
    end
  end
  return table.concat(parts, "/")
end

local function directory_of(path)
  return path:match("^(.*)/[^/]*$") or ""
end

-- the anchor of a whole note: "chapters/04_integral_matching/README.md" -> "chapters-04_integral_matching",
-- its evidence "chapters/04_integral_matching/EVIDENCE.md" -> "chapters-04_integral_matching-evidence",
-- a page of docs/ "docs/speed.md" -> "docs-speed"
local function key_of(path)
  local folder = directory_of(path)
  local name = path:match("([^/]*)$"):gsub("%.md$", "")
  local base = folder == "" and "introduction" or (folder:gsub("/", "-"))
  if name == "README" then
    return base
  end
  return (folder == "" and "" or base .. "-") .. name:lower()
end

local function is_external(target)
  return target:match("^%a[%w+.-]*:") ~= nil
end

local source, key, book_files, retitle = nil, nil, {}, nil

local function read_meta(meta)
  source = pandoc.utils.stringify(meta.source or "")
  key = key_of(source)
  for _, file in ipairs(meta.book_files or {}) do
    book_files[pandoc.utils.stringify(file)] = true
  end
  if meta.retitle then
    retitle = pandoc.utils.stringify(meta.retitle)
  end
end

local function resolve(relative)
  return normalize(directory_of(source) .. "/" .. relative)
end

local first_heading_seen = false

local function header(h)
  if not first_heading_seen then
    first_heading_seen = true
    h.identifier = key
    if retitle then
      h.content = pandoc.Inlines(retitle)
    end
  else
    -- GitHub drops the periods of a heading's anchor ("theorem-51" for "Theorem 5.1"), pandoc
    -- keeps them: the book drops them too, so that links written for GitHub find their heading
    h.identifier = key .. "--" .. h.identifier:gsub("%.", "")
  end
  return h
end

local function image(img)
  if is_external(img.src) then
    return img
  end
  local path = resolve(img.src)
  if not file_exists(path) then
    return pandoc.Emph({ pandoc.Str("[figure " .. path .. " not generated yet]") })
  end
  img.src = path
  -- the HTML embeds the image as data, so its file is named in an attribute (data-file)
  img.attributes.file = path
  return img
end

local function link(l)
  local target = l.target
  if is_external(target) then
    return l
  end
  local file, fragment = target:match("^([^#]*)#?(.*)$")
  fragment = fragment:gsub("%.", "")  -- the headings' anchors have no periods (header above)
  if file == "" then
    l.target = "#" .. key .. "--" .. fragment
    return l
  end
  local path = resolve(file)
  if book_files[path] then
    l.target = "#" .. key_of(path) .. (fragment ~= "" and ("--" .. fragment) or "")
    return l
  end
  return l.content
end

-- texmath (pandoc's MathML writer) does not know the old-style font switch {\rm ref}: write
-- it \mathrm{ref}, which both MathML and LaTeX read
local function plain_math(m)
  m.text = m.text:gsub("{\\rm%s+([^{}]*)}", "\\mathrm{%1}")
  return m
end

-- second pass, LaTeX: prefer the PDF twin of a PNG figure
local function latex_image(img)
  local pdf = img.src:gsub("%.png$", ".pdf")
  if pdf ~= img.src and file_exists(pdf) then
    img.src = pdf
  end
  return img
end

-- second pass, LaTeX: a code name (tests are named like Programs.ch05_rho_too_large_is_...)
-- may break after its underscores, dots, slashes, commas and equal signs, or it runs out of
-- its table cell
local latex_escapes = {
  ["\\"] = "\\textbackslash{}", ["{"] = "\\{", ["}"] = "\\}", ["$"] = "\\$", ["&"] = "\\&",
  ["#"] = "\\#", ["%"] = "\\%", ["^"] = "\\textasciicircum{}", ["~"] = "\\textasciitilde{}",
  ["_"] = "\\_", ["-"] = "-{}",
}
local function latex_code(code)
  local text = code.text:gsub("[\\{}$&#%%^~_-]", latex_escapes)
  text = text:gsub("([_./,=]+)", "%1\\allowbreak{}")
  return pandoc.RawInline("latex", "\\texttt{" .. text .. "}")
end

-- second pass, LaTeX: columns as wide as their text, at least a tenth of the line, so that a
-- column of short words does not take the room a column of sentences needs
local function latex_table(tbl)
  local lengths = {}
  local function count(rows)
    for _, row in ipairs(rows) do
      for j, cell in ipairs(row.cells) do
        lengths[j] = (lengths[j] or 0) + #pandoc.utils.stringify(cell.contents)
      end
    end
  end
  count(tbl.head.rows)
  for _, body in ipairs(tbl.bodies) do
    count(body.body)
  end
  local total = 0
  for j = 1, #tbl.colspecs do
    total = total + (lengths[j] or 0)
  end
  if total == 0 then
    return nil
  end
  local widths, sum = {}, 0
  for j = 1, #tbl.colspecs do
    widths[j] = math.max((lengths[j] or 0) / total, 0.1)
    sum = sum + widths[j]
  end
  for j = 1, #tbl.colspecs do
    tbl.colspecs[j] = { tbl.colspecs[j][1], 0.97 * widths[j] / sum }
  end
  return tbl
end

-- second pass, LaTeX: program output and commands in a smaller font, long lines broken and
-- marked (fvextra's Verbatim, book/header.tex) rather than running off the page
local function latex_code_block(block)
  return pandoc.RawBlock("latex", "\\begin{Verbatim}[breaklines,breakanywhere,fontsize=\\small]\n"
    .. block.text .. "\n\\end{Verbatim}")
end

if FORMAT:match("latex") then
  -- the tables first: they measure the code names before these become raw LaTeX
  return { { Table = latex_table }, { Image = latex_image, Code = latex_code, CodeBlock = latex_code_block } }
end
if FORMAT:match("markdown") then
  return {
    { Meta = read_meta },
    { Header = header, Image = image, Link = link, Math = plain_math },
  }
end
return {}
