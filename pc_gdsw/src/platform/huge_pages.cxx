// SPDX-License-Identifier: BSD-2-Clause
/* The local factors on transparent huge pages.

   A fresh set-up writes every local factor to memory touched for the first time. Where the
   kernel gives transparent huge pages only on request (/sys/kernel/mm/transparent_hugepage/enabled
   is "madvise", the default of Debian and Ubuntu), each 4 KiB page of them costs a page fault,
   several microseconds in a virtual machine: the fresh set-up's factorisations spent most of
   their time there. CHOLMOD and UMFPACK allocate through SuiteSparse_config; during the set-up's
   steps that make blocks it keeps (gdsw.cxx: the subdomain matrices, the first level's factors),
   their blocks of 2 MiB or more, and gdsw's own, are mapped here, aligned to 2 MiB and advised
   MADV_HUGEPAGE (what glibc.malloc.hugetlb=1 does for a whole process). Any other block goes to
   the functions installed before. A block freed during such a step (CHOLMOD's workspace for one
   subdomain) is kept for the next one of about its size, as malloc() would reuse its heap,
   instead of being mapped and faulted in again; the kept ones are unmapped when the step ends.
   The hooks stay installed once set, because a block mapped here may be freed long after (the
   library is linked with -z nodelete, so that a dlclose() cannot unmap them). */
#include "../gdswimpl.h"
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <unordered_map>
#include <vector>
#include <SuiteSparse_config.h>
#if defined(__linux__)
  #include <sys/mman.h>
#endif

namespace {
#if defined(MADV_HUGEPAGE)

constexpr size_t hugePage = (size_t)2 << 20;
constexpr size_t spareMax = (size_t)256 << 20; /* bytes kept for reuse at most */

struct Hooks {
  void *(*malloc_func)(size_t);
  void *(*calloc_func)(size_t, size_t);
  void *(*realloc_func)(void *, size_t);
  void (*free_func)(void *);
};

/* A mapping made here: len bytes from base, a huge page boundary */
struct Block {
  char  *base;
  size_t len;
};

Hooks       previous;
int         active = 0; /* set-ups in progress */
size_t      handedOut = 0, spareBytes = 0;
std::mutex *lock; /* never destroyed: frees may come during exit */
std::unordered_map<void *, Block> *mapped; /* by the block's address */
std::vector<Block>                *spare;  /* freed during a set-up, oldest first */

/* A kept block for n bytes, not much larger, taken out of the spares (lock held) */
void *TakeSpare(size_t n)
{
  auto best = spare->end();
  for (auto it = spare->begin(); it != spare->end(); ++it)
    if (it->len >= n && it->len <= n + n / 4 && (best == spare->end() || it->len < best->len)) best = it;
  if (best == spare->end()) return nullptr;
  void *p = best->base;
  spareBytes -= best->len;
  (*mapped)[p] = *best;
  spare->erase(best);
  return p;
}

/* n bytes on huge pages, reused or freshly mapped (*fresh: zero), or nullptr */
void *MapHuge(size_t n, bool *fresh)
{
  {
    std::lock_guard<std::mutex> guard(*lock);
    void                       *p = TakeSpare(n);
    *fresh                        = !p;
    if (p) {
      handedOut += n;
      return p;
    }
  }
  const size_t len = (n + 4095) & ~(size_t)4095;
  char        *raw = (char *)mmap(nullptr, len + hugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  char        *base = (char *)(((uintptr_t)raw + hugePage - 1) & ~(uintptr_t)(hugePage - 1));
  const size_t head = (size_t)(base - raw);
  if (head) munmap(raw, head);
  munmap(base + len, hugePage - head);
  madvise(base, len, MADV_HUGEPAGE);
  std::lock_guard<std::mutex> guard(*lock);
  (*mapped)[base] = {base, len};
  handedOut += n;
  return base;
}

/* The block at p if it was mapped here, forgotten if asked */
bool Mapped(void *p, bool forget, Block *b)
{
  std::lock_guard<std::mutex> guard(*lock);
  auto                        it = p ? mapped->find(p) : mapped->end();
  if (it == mapped->end()) return false;
  *b = it->second;
  if (forget) mapped->erase(it);
  return true;
}

bool Wanted(size_t n)
{
  std::lock_guard<std::mutex> guard(*lock);
  return active > 0 && n >= hugePage;
}

/* Frees p if it was mapped here (kept for reuse during a set-up); false if it was not */
bool FreeMapped(void *p)
{
  Block b;
  if (!Mapped(p, true, &b)) return false;
  std::vector<Block> drop;
  {
    std::lock_guard<std::mutex> guard(*lock);
    if (active > 0) {
      spare->push_back(b);
      spareBytes += b.len;
      while (spareBytes > spareMax) {
        drop.push_back(spare->front());
        spareBytes -= spare->front().len;
        spare->erase(spare->begin());
      }
    } else drop.push_back(b);
  }
  for (const Block &d : drop) munmap(d.base, d.len);
  return true;
}

void *HugeMalloc(size_t n)
{
  bool  fresh;
  void *p = Wanted(n) ? MapHuge(n, &fresh) : nullptr;
  return p ? p : previous.malloc_func(n);
}

void *HugeCalloc(size_t count, size_t size)
{
  bool  fresh = true;
  void *p     = (size && count <= SIZE_MAX / size && Wanted(count * size)) ? MapHuge(count * size, &fresh) : nullptr;
  if (!p) return previous.calloc_func(count, size);
  if (!fresh) std::memset(p, 0, count * size); /* a fresh mapping is zero already */
  return p;
}

void HugeFree(void *p)
{
  if (!FreeMapped(p)) previous.free_func(p);
}

void *HugeRealloc(void *p, size_t n)
{
  Block b;
  if (!Mapped(p, false, &b)) return previous.realloc_func(p, n);
  void *q = HugeMalloc(n);
  if (!q) return nullptr; /* p stays valid, as realloc() promises */
  std::memcpy(q, p, b.len < n ? b.len : n);
  HugeFree(p);
  return q;
}

/* SuiteSparse's allocation functions: SuiteSparse 7 reads and sets them through accessors, the
   struct SuiteSparse_config of the earlier versions is no longer public */
Hooks GetHooks()
{
#if SUITESPARSE_MAIN_VERSION >= 7
  return {SuiteSparse_config_malloc_func_get(), SuiteSparse_config_calloc_func_get(), SuiteSparse_config_realloc_func_get(), SuiteSparse_config_free_func_get()};
#else
  return {SuiteSparse_config.malloc_func, SuiteSparse_config.calloc_func, SuiteSparse_config.realloc_func, SuiteSparse_config.free_func};
#endif
}

void SetHooks(const Hooks &h)
{
#if SUITESPARSE_MAIN_VERSION >= 7
  SuiteSparse_config_malloc_func_set(h.malloc_func);
  SuiteSparse_config_calloc_func_set(h.calloc_func);
  SuiteSparse_config_realloc_func_set(h.realloc_func);
  SuiteSparse_config_free_func_set(h.free_func);
#else
  SuiteSparse_config.malloc_func  = h.malloc_func;
  SuiteSparse_config.calloc_func  = h.calloc_func;
  SuiteSparse_config.realloc_func = h.realloc_func;
  SuiteSparse_config.free_func    = h.free_func;
#endif
}

/* Only where huge pages are given on request: "always" gives them anyway, "never" not at all */
bool OnRequest()
{
  char  mode[128] = "";
  FILE *f         = std::fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
  if (!f) return false;
  const bool ok = std::fgets(mode, sizeof(mode), f) != nullptr;
  std::fclose(f);
  return ok && std::strstr(mode, "[madvise]") != nullptr;
}
#endif

} // namespace

/* Starts a span of huge-page allocations; *began says whether it did and *mark where the count
   stood, for the end */
PetscErrorCode GDSWHugePagesBegin(PC pc, PetscBool use, PetscBool *began, size_t *mark)
{
  PetscFunctionBegin;
  *began = PETSC_FALSE;
  *mark  = 0;
  if (!use) PetscFunctionReturn(0);
#if !defined(MADV_HUGEPAGE)
  PetscCall(PetscInfo(pc, "no transparent huge pages on this system: -pc_gdsw_huge_pages changes nothing\n"));
#else
  static const bool installed = [] {
    if (!OnRequest()) return false;
    lock                             = new std::mutex;
    mapped                           = new std::unordered_map<void *, Block>;
    spare                            = new std::vector<Block>;
    previous                         = GetHooks();
    SetHooks({HugeMalloc, HugeCalloc, HugeRealloc, HugeFree});
    return true;
  }();
  static bool told = false;
  if (!told) PetscCall(PetscInfo(pc, installed ? "the set-up's blocks of 2 MiB or more go on transparent huge pages (the kernel gives them on request)\n" : "transparent huge pages are not given on request here (/sys/kernel/mm/transparent_hugepage/enabled is not madvise): -pc_gdsw_huge_pages changes nothing\n"));
  told = true;
  if (!installed) PetscFunctionReturn(0);
  std::lock_guard<std::mutex> guard(*lock);
  active++;
  *began = PETSC_TRUE;
  *mark  = handedOut;
#endif
  PetscFunctionReturn(0);
}

/* Ends the span; *bytes: what it gave out on huge pages */
PetscErrorCode GDSWHugePagesEnd(PetscBool began, size_t mark, size_t *bytes)
{
  PetscFunctionBegin;
  *bytes = 0;
#if defined(MADV_HUGEPAGE)
  if (!began) PetscFunctionReturn(0);
  std::vector<Block> drop;
  {
    std::lock_guard<std::mutex> guard(*lock);
    *bytes = handedOut - mark;
    if (--active == 0) {
      drop.swap(*spare);
      spareBytes = 0;
    }
  }
  for (const Block &d : drop) munmap(d.base, d.len);
#endif
  PetscFunctionReturn(0);
}

/* gdsw's own large arrays (the subdomain matrices) by the same rule; the others from malloc() */
void *GDSWHugeMalloc(size_t n)
{
#if defined(MADV_HUGEPAGE)
  bool  fresh;
  void *p = lock && Wanted(n) ? MapHuge(n, &fresh) : nullptr;
  if (p) return p;
#endif
  return std::malloc(n);
}

void GDSWHugeFree(void *p)
{
#if defined(MADV_HUGEPAGE)
  if (lock && FreeMapped(p)) return;
#endif
  std::free(p);
}
